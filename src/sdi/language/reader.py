"""The offline Specifier: a command → a `Reading` (structures, relations, notes).

The command is read in stages:

1. **Normalise and correct**: symbols, ``3x3`` → ``3 x 3``; unknown words close to a known
   word are corrected (`sdi.language.typos`); negations and hedges with a clear reading are
   rewritten ("not too tall" → medium, "not on the left" → on the right, "don't stack them"
   → side by side), each with a note.
2. **Parse** with spaCy's dependency parser (`sdi.language.syntax`).
3. **Clauses**: sentences, ``;`` and sequence words ("then", "after that") separate clauses;
   a clause that names no structure continues the one before ("Make it 5 high").
4. **Relations**: markers such as "on top of", "around", "surround … with", "next to",
   "to the left of", "joined by", "connecting" relate the noun phrase before them to the one
   after (or, for verbs, the verb's object to the phrase after "with"). A marker is a
   relation only if its object is a structure, a pronoun ("it", "them") or a definite
   reference to an earlier structure ("the base"); "on the left" stays a region.
5. **Slot filling**: each phrase is read by the phrase grammar (`sdi.spec.grammar`), which
   fills the family's slots (counts, levels, sizes, regions, coordinates).
6. **Composition**: pronouns and "the base" resolve to earlier phrases; "a second row"
   copies the row it refers to; two towers "joined by" a beam become a bridge on them.
7. **Accounting**: every word is used or reported; unused material words make the reading
   incomplete (`Reading.complete` is False, the plan is ``partial``).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from sdi.errors import LimitError, SpecError
from sdi.language import typos, words
from sdi.language.families import check_family
from sdi.language.reading import Reading
from sdi.language.syntax import parse
from sdi.model.cell import CellConfig
from sdi.spec import lexicon as lx
from sdi.spec.grammar import parse_phrase
from sdi.spec.numbers import words_to_numbers
from sdi.spec.structure_spec import Relation, RelationKind, Spec, StructureSpec

if TYPE_CHECKING:
    from spacy.tokens import Doc, Token

_SYMBOLS = {"×": " x ", "–": "-", "—": "-", "’": "'", "\u00a0": " "}
_DIMS = re.compile(r"(?<=\d)\s*[x*]\s*(?=\d)", re.IGNORECASE)
_SPACES = re.compile(r"\s+")

# Sequence words that start a new clause.
_SEQUENCE = {"then", "afterwards", "finally", "lastly", "next", "after"}
_LEADS = {"first", "firstly", "and", ",", "after", "that", "then", "next", "finally", "also"}

# Relation markers: words → (kind, side). Kinds: on (subject on object), around (subject
# encloses object), inside (object encloses subject), next (beside, `side`), join (subject
# joins the object's pillars), joined (the object joins the subject's pillars).
_MARKERS: list[tuple[tuple[str, ...], str, str | None]] = [
    (("on", "the", "middle", "of"), "on", None),
    (("on", "the", "centre", "of"), "on", None),
    (("on", "the", "center", "of"), "on", None),
    (("across", "the", "top", "of"), "on", None),
    (("across",), "on", None),
    (("on", "top", "of"), "on", None),
    (("on", "the", "top", "of"), "on", None),
    (("on", "top"), "on", None),
    (("onto",), "on", None),
    (("atop",), "on", None),
    (("upon",), "on", None),
    (("above",), "on", None),
    (("over",), "on", None),
    (("on",), "on", None),
    (("underneath",), "under", None),
    (("beneath",), "under", None),
    (("below",), "under", None),
    (("under",), "under", None),
    (("around",), "around", None),
    (("round",), "around", None),
    (("surrounding",), "around", None),
    (("enclosing",), "around", None),
    (("encircling",), "around", None),
    (("in",), "inside_ref", None),
    (("into",), "inside_ref", None),
    (("inside", "of"), "inside", None),
    (("inside",), "inside", None),
    (("within",), "inside", None),
    (("in", "the", "middle", "of"), "inside", None),
    (("in", "the", "centre", "of"), "inside", None),
    (("in", "the", "center", "of"), "inside", None),
    (("surrounded", "by"), "inside", None),
    (("enclosed", "by"), "inside", None),
    (("enclosed", "in"), "inside", None),
    (("encircled", "by"), "inside", None),
    (("ringed", "by"), "inside", None),
    (("next", "to"), "next", None),
    (("beside",), "next", None),
    (("besides",), "next", None),
    (("alongside", "it"), "next_implicit", None),
    (("alongside",), "next", None),
    (("adjacent", "to"), "next", None),
    (("close", "to"), "next", None),
    (("near", "to"), "next", None),
    (("leading", "up", "to"), "next", None),
    (("leading", "to"), "next", None),
    (("near",), "next", None),
    (("to", "its", "left"), "next_implicit", "left"),
    (("to", "its", "right"), "next_implicit", "right"),
    (("on", "its", "left"), "next_implicit", "left"),
    (("on", "its", "right"), "next_implicit", "right"),
    (("in", "front", "of", "it"), "next_implicit", "front"),
    (("behind", "it"), "next_implicit", "back"),
    (("to", "the", "left", "of"), "next", "left"),
    (("on", "the", "left", "of"), "next", "left"),
    (("left", "of"), "next", "left"),
    (("to", "the", "right", "of"), "next", "right"),
    (("on", "the", "right", "of"), "next", "right"),
    (("right", "of"), "next", "right"),
    (("in", "front", "of"), "next", "front"),
    (("behind",), "next", "back"),
    (("at", "the", "back", "of"), "next", "back"),
    (("joined", "at", "the", "top", "by"), "joined", None),
    (("connected", "at", "the", "top", "by"), "joined", None),
    (("joined", "on", "top", "by"), "joined", None),
    (("joined", "on", "top", "with"), "joined", None),
    (("joined", "at", "the", "top", "with"), "joined", None),
    (("connected", "on", "top", "with"), "joined", None),
    (("connected", "on", "top", "by"), "joined", None),
    (("joined", "together", "by"), "joined", None),
    (("joined", "by"), "joined", None),
    (("connected", "by"), "joined", None),
    (("linked", "by"), "joined", None),
    (("bridged", "by"), "joined", None),
    (("spanned", "by"), "joined", None),
    (("joined", "with"), "joined", None),
    (("connected", "with"), "joined", None),
    (("topped", "by"), "topped", None),
    (("topped", "with"), "topped", None),
    (("capped", "by"), "topped", None),
    (("capped", "with"), "topped", None),
    (("joining",), "join", None),
    (("connecting",), "join", None),
    (("linking",), "join", None),
    (("bridging",), "join", None),
    (("spanning",), "join", None),
    (("between",), "join", None),
]
_MARKERS.sort(key=lambda m: -len(m[0]))
_VERB_AROUND = {"surround", "encircle", "enclose", "ring", "circle", "fence", "wall"}
_VERB_JOIN = {"join", "connect", "link", "bridge", "span"}
_VERB_TOP = {"top", "cap", "crown"}
_PRONOUNS = {"it", "them", "this", "that", "these", "those", "one", "both"}
# Nouns that name a structure in a relation but not a family of their own.
_GENERIC = {"platform", "slab", "plinth", "pedestal", "layer", "floor", "level", "tier",
            "structure", "thing", "one", "first", "last", "other"}  # fmt: skip
# "a ziggurat on a 3 by 3 base" is the ziggurat's own base; "on top of the base" is another
# structure (and so is "a base layer"): these nouns name a structure only after "on top of".
_BASES = {"base", "foundation", "bottom", "footing", "footprint"}
_BEAMS = {"beam", "beams", "plank", "planks", "lintel", "lintels", "girder", "girders", "bar",
          "slab", "bridge", "bridges", "arch", "roof", "deck", "span"}  # fmt: skip
_FRONTED_VERBS = {"goes", "go", "stands", "sits", "comes", "is", "are", "put", "place", "build",
                  "add", "stack", "lies", "rests", "belongs", "should", "will", "must"}  # fmt: skip
_LEAD_VERBS = {"put", "place", "set", "add", "make", "build", "stack", "lay", "position", "move"}
_ORDINALS = {"first", "second", "third", "fourth", "last", "other"}
_QUANTITY_NOUNS = {"pair", "couple", "set", "group", "bunch", "handful", "trio"}
_EMPTY = {"empty", "hollow", "open", "free", "blank"}
_COPY = {"second", "another", "same", "identical", "matching", "similar", "twin", "copy"}
_KINDS: dict[str, RelationKind] = {"on": "on_top_of", "around": "around", "next": "next_to"}
_OPPOSITE = {"left": "right", "right": "left", "front": "back", "back": "front",
             "middle": "left", "centre": "left", "center": "left"}  # fmt: skip
_LEVEL_ORDINAL = re.compile(
    r"\b(?:as|for|on|to form)\s+(?:the|a)\s+(?:second|third|fourth|fifth|next|top|final|last|"
    r"upper|new)\s+(?:level|layer|tier|storey|story|floor|row)\b",
    re.IGNORECASE,
)

# Negations and hedges with one clear reading: (pattern, replacement, note).
_REWRITES: list[tuple[re.Pattern[str], str, str]] = [
    (
        re.compile(
            r"(?:,\s*)?\b(?:but\s+|and\s+)?(?:(?:that|which)\s+is\s+|that's\s+)?not\s+"
            r"(?:too|very|so|overly|that|excessively|all\s+that)\s+"
            r"(?:tall|high|big|large|long|wide|huge|massive)\b",
            re.IGNORECASE,
        ),
        " medium ",
        "read '{0}' as a medium size",
    ),
    (
        re.compile(
            r"(?:,\s*)?\b(?:but\s+|and\s+)?not\s+(?:too|very|so)\s+"
            r"(?:small|short|low|tiny|little)\b",
            re.IGNORECASE,
        ),
        " medium ",
        "read '{0}' as a medium size",
    ),
    (
        re.compile(
            r"\b(?:(?:that|which)\s+(?:is|are)\s+|that's\s+|but\s+|and\s+|is\s+)?not\s+"
            r"(?:on|in|at|to)\s+the\s+(left|right|front|back|middle|centre|center)(?:\s+side)?\b",
            re.IGNORECASE,
        ),
        " on the {opposite} ",
        "read '{0}' as on the {opposite}",
    ),
    (
        re.compile(
            r"(?:,\s*)?\b(?:but\s+|and\s+)?(?:please\s+)?(?:do\s+not|don't|dont|never|no\s+need\s+"
            r"to)\s+(?:stack|pile|put\s+\w+\s+on\s+top)\b(?:\s+(?:them|it|the\s+cubes|anything))?"
            r"(?:\s+(?:up|on\s+top(?:\s+of\s+each\s+other)?))?",
            re.IGNORECASE,
        ),
        "{no_stack}",
        "'{0}': laid side by side, not stacked",
    ),
    (
        re.compile(r"(?:,\s*)?\b(?:with\s+)?no\s+stacking\b", re.IGNORECASE),
        "{no_stack}",
        "'{0}': laid side by side, not stacked",
    ),
    (
        re.compile(
            r"\bwith\s+(?:a|one|an)\s+(bridge|beam|lintel|plank|slab|arch|girder)\s+"
            r"(?:between\s+them|across(?:\s+the\s+top|\s+them)?|on\s+top|connecting\s+them|"
            r"joining\s+them|linking\s+them|spanning\s+them)\b",
            re.IGNORECASE,
        ),
        " joined by a {0} ",
        "",
    ),
]
_REWRITES += [
    (
        re.compile(
            r"\b(?:whose|with\s+(?:a|the|its))\s+(?:bottom|base|lowest|first|ground)\s+"
            r"(?:row|layer|level|tier|course)\s+(?:has|having|of|with|is|containing|holds|"
            r"holding|made\s+of)?\s*(\d+|[a-z]+)",
            re.IGNORECASE,
        ),
        " with a base of {0} ",
        "",
    ),
    (
        re.compile(
            r"\b(?:with\s+)?one\s+(?:leg|arm|side|wing|branch)\s+(\d+|[a-z]+)(?:\s+\w+)?\s+"
            r"long\s*,?\s+and\s+the\s+other(?:\s+(?:leg|arm|side|wing|one|branch))?\s+"
            r"(\d+|[a-z]+)(?:\s+\w+)?\s+long\b",
            re.IGNORECASE,
        ),
        " {0} long and {1} wide ",
        "",
    ),
    (re.compile(r"\bside\s+by\s+side\b", re.IGNORECASE), " ", ""),
]
_SHAPE_ALT = "|".join(sorted((w for w in lx.SHAPE_WORDS if w.isalpha()), key=len, reverse=True))
_REWRITES += [
    # "anywhere except the back", "anywhere but on the left", "avoid the left side"
    (
        re.compile(
            r"\b(?:anywhere\s+)?(?:except|but\s+not|other\s+than|apart\s+from|away\s+from|"
            r"avoid(?:ing)?)\s+(?:on\s+|in\s+|at\s+)?the\s+(left|right|front|back|middle|centre|"
            r"center)(?:\s+side)?(?:\s+(?:or|and|nor)\s+(?:on\s+|in\s+|at\s+)?the\s+"
            r"(left|right|front|back)(?:\s+side)?)?\b",
            re.IGNORECASE,
        ),
        " on the {opposite} {opposite2} ",
        "read '{0}' as on the {opposite} {opposite2}",
    ),
    (
        re.compile(
            r"(?:^|(?<=[.;,:]))\s*(?:no|not\s+an?)\s+(?:"
            + _SHAPE_ALT
            + r")s?\s+(?:this\s+time|today|"
            r"now|please)\s*[,:;.-]*\s*(?:just|only|but|instead)?",
            re.IGNORECASE,
        ),
        " ",
        "left out what is not wanted: '{0}'",
    ),
    (
        re.compile(
            r",?\s*\bnot\s+a\s+(?:square|round|big|small|tall|short|flat)\s+one\s*[:,;-]?", re.I
        ),
        " , ",
        "'{0}': as the sizes say",
    ),
    (
        re.compile(r",?\s*-?\s*\b(?:cubes|blocks)\s+only\b|\bonly\s+cubes\b", re.I),
        "{no_beams}",
        "'{0}': built of cubes only",
    ),
    (
        re.compile(
            r"\b(one|a)\s+(\w+)(\s+of\s+\d+)?\s+on\s+each\s+side(?:\s*,?\s*(?:the\s+)?left\s+and\s+"
            r"(?:the\s+)?right)?\b",
            re.IGNORECASE,
        ),
        " {0} {1}{2} on the left and another {1}{2} on the right ",
        "",
    ),
    (
        re.compile(
            r",?\s*\b(?:climbing|rising|ascending|going\s+up|stepping\s+up)\s+(?:to(?:wards)?|toward|"
            r"to\s+the)\s+(?:the\s+)?(left|right|front|back)\b",
            re.IGNORECASE,
        ),
        "{climb}",
        "",
    ),
    (
        re.compile(
            r"\b(?:does|do)\s+not\s+(?:go|rise|reach|get)\s+(?:any\s+)?(?:taller|higher)\s+than\s+"
            r"(\d+|[a-z]+)(\s+(?:cubes?|parts?|blocks?|levels?|layers?|cm|mm|m))?",
            re.IGNORECASE,
        ),
        " {0}{1} high ",
        "read '{0}' as exactly that (the most allowed)",
    ),
    (
        re.compile(
            r"\b(\d+|[a-z]+)\s+(?:cubes?\s+)?(?:wide|across|long)\s+at\s+the\s+(?:bottom|base)\b",
            re.IGNORECASE,
        ),
        " with a base of {0} ",
        "",
    ),
    (
        re.compile(
            r"\b(?:a|one)\s+(?:single|lone|solitary)\s+(?:cube|block|brick)\b"
            r"(?!\s*(?:-|tower|stack|column|wall|row|high|tall))",
            re.IGNORECASE,
        ),
        " a 1-cube tower ",
        "",
    ),
    (
        re.compile(r"\bnot\s+(?:one|a\s+single)\s+but\s+(two|three|four|five|\d+)\b", re.I),
        " {0} ",
        "",
    ),
    (
        re.compile(r"\bon\s+(?:its|the)\s+(?:centre|center|middle|top)\b(?!\s+of)", re.I),
        " on top ",
        "",
    ),
    # "no taller than 2 cubes" → 2 cubes high; "no more than 3 steps" → 3 steps
    (
        re.compile(
            r"\b(?:no|not)\s+(?:taller|higher)\s+than\s+(\d+|[a-z]+)"
            r"(\s+(?:cubes?|parts?|blocks?|levels?|layers?))?",
            re.IGNORECASE,
        ),
        " {0}{1} high ",
        "read '{0}' as exactly that many (the most allowed)",
    ),
    (
        re.compile(r"\b(?:no|not)\s+(?:more|longer|wider|bigger)\s+than\s+|\bat\s+most\s+", re.I),
        " ",
        "read '{0}' as exactly that many (the most allowed)",
    ),
    # "a tower of 4, not 5": the number that is not wanted
    (
        re.compile(
            r",?\s*\b(?:but\s+)?not\s+(\d+)\b(?!\s*(?:cm|mm|m\b|high|tall|long|wide))", re.I
        ),
        " ",
        "'{0}': kept the other number",
    ),
    # "no beams, only cubes": cubes are the default part
    (
        re.compile(
            r",?\s*\b(?:no|without)\s+beams?\b,?(?:\s*(?:just|only)\s+cubes)?|"
            r",?\s*\b(?:just|only)\s+cubes\b",
            re.IGNORECASE,
        ),
        "{no_beams}",
        "'{0}': built of cubes only",
    ),
    # "a 3x3 grid without the middle cube": a ring
    (
        re.compile(
            r"\b(grid|square|layer|slab|pad|patch|platform)\s+(?:of\s+cubes\s+)?without\s+"
            r"(?:the\s+|a\s+)?(?:middle|centre|center|inner|central)(?:\s+(?:cube|one|part|piece))?",
            re.IGNORECASE,
        ),
        " hollow {0} ",
        "read '{0}' as a hollow ring",
    ),
    # "an enclosure with no roof and nothing inside": what an enclosure is anyway
    (
        re.compile(
            r"\b(?:with\s+)?(?:no|without\s+a|without)\s+roof\b|\b(?:and\s+)?nothing\s+(?:else\s+)?"
            r"inside\b",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': as an enclosure is",
    ),
    # "a castle without the corner towers": a ring
    (
        re.compile(
            r"\bcastle\s+without\s+(?:the\s+|any\s+)?(?:corner\s+)?towers\b(?:,?\s*just\s+the\s+"
            r"walls?(?:\s+around)?)?",
            re.IGNORECASE,
        ),
        " enclosure ",
        "read '{0}' as an enclosure (a castle is a ring with corner towers)",
    ),
    # "not a 3-D one, just flat" for pyramids
    (
        re.compile(
            r",?\s*\b(?:but\s+)?not\s+(?:a\s+)?3-?d(?:\s+one)?,?(?:\s+just)?(?:\s+flat)?", re.I
        ),
        " 2-D ",
        "read '{0}' as a flat (2-D) one",
    ),
    # "not a tower: a flat 2 by 2 patch", "no bridge, just two pillars"
    (
        re.compile(
            r"(?:^|(?<=[.;,:]))\s*(?:no|not\s+an?|not|without\s+an?)\s+(?:" + _SHAPE_ALT + r")\b"
            r"\s*[,:;.-]+\s*(?:just|only|but|instead)?",
            re.IGNORECASE,
        ),
        " ",
        "left out what is not wanted: '{0}'",
    ),
    # "as tall as the cell allows" → the tallest
    (
        re.compile(
            r"\bas\s+(tall|high)\s+as\s+(?:the\s+(?:cell|workspace|space|robot|room)\s+"
            r"(?:allows|permits|can\s+\w+)|possible|it\s+can\s+(?:go|get|be)|you\s+can(?:\s+\w+)?|"
            r"allowed)",
            re.IGNORECASE,
        ),
        " tallest ",
        "read '{0}' as the tallest that fits",
    ),
    # "3 stacks: one of 1, one of 2 and one of 3 cubes" → of 1, 2 and 3 cubes
    (
        re.compile(
            r"[:,]?\s*\bone\s+of\s+(\w+)(?:\s+(?:cubes?|parts?|blocks?))?\s*(?:,|and)\s*(?:the\s+other\s+|one\s+)of"
            r"\s+(\w+)(?:\s+(?:cubes?|parts?|blocks?))?"
            r"(?:\s*(?:,|and)\s*(?:one\s+of\s+)?(\w+)(?:\s+(?:cubes?|parts?|blocks?))?)?",
            re.IGNORECASE,
        ),
        " of {0}, {1} and {2} ",
        "",
    ),
    # "stack a row of four on top": the verb names no tower when a structure follows
    (
        re.compile(
            r"\b(?:stack|pile)\s+(?=(?:a|an|the|another|one|\d+|two|three|four)\s+(?:[\w-]+\s+){0,3}"
            r"(?:row|rows|grid|wall|layer|slab|pyramid|staircase|bridge|arch|ring|enclosure|pad|"
            r"square|platform)\b)",
            re.IGNORECASE,
        ),
        "put ",
        "",
    ),
    (re.compile(r"\b(?:on|at)\s+the\s+(?:very\s+)?top\b(?!\s+of)", re.IGNORECASE), " on top ", ""),
    (re.compile(r"\b(?:thanks|thank\s+you)(?:\s+a\s+lot|\s+so\s+much)?\b", re.I), " ", ""),
    (re.compile(r"\bnothing\s+(?:fancy|else|special|more)\b", re.IGNORECASE), " ", ""),
    (
        re.compile(
            r"(?:\bStep\s+(?:\d+|one|two|three|four|five|six)\s*[:.)-]|(?:^|(?<=[.;]))\s*"
            r"(?:one|two|three|four|five|six|first|second|third|fourth|fifth|last|finally)\s*[:,]"
            r"(?=\s*(?:a|an|the|\d|one|put|add|place|lay|build|stack|make|then)\b))",
            re.IGNORECASE,
        ),
        " then ",
        "",
    ),
    (
        re.compile(
            r",?\s*\b(?:with\s+|and\s+|then\s+build\s+)?(?:each|every)\s+(?:level|layer|row|tier)\s+"
            r"(?:exactly\s+)?(?:like|the\s+same\s+as|identical\s+to|matching)\s+the\s+one\s+"
            r"(?:below|under(?:neath)?|beneath)(?:\s+it)?",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': every level the same",
    ),
]
_REWRITES += [
    (
        re.compile(
            r"\b(?:but\s+|and\s+)?(?:do\s+not|never)\s+(?:put|place|build|set)\s+(?:it|them)\s+"
            r"(?:on|in|at|to)\s+the\s+(left|right|front|back|middle|centre|center)(?:\s+side)?\b",
            re.IGNORECASE,
        ),
        " on the {opposite} ",
        "read '{0}' as on the {opposite}",
    ),
    (
        re.compile(
            r"\b(?:(?:and\s+)?keep\s+(?:it|them)\s+)away\s+from\s+the\s+"
            r"(left|right|front|back)(?:\s+side)?\b",
            re.IGNORECASE,
        ),
        " on the {opposite} ",
        "read '{0}' as on the {opposite}",
    ),
    (
        re.compile(
            r"\bneither\s+(?:on|in|at)\s+the\s+(?:left|right|front|back)\s+nor\s+(?:on|in|at)\s+"
            r"the\s+(?:left|right|front|back)\b",
            re.IGNORECASE,
        ),
        " in the centre ",
        "read '{0}' as in the centre",
    ),
    (
        re.compile(
            r"\b(?:never|not\s+ever)\s+(?:taller|higher)\s+than\s+(\d+|[a-z]+)"
            r"(\s+(?:cubes?|parts?|blocks?|levels?|layers?))?",
            re.IGNORECASE,
        ),
        " {0}{1} high ",
        "read '{0}' as exactly that many (the most allowed)",
    ),
    (
        re.compile(
            r",?\s*\b(?:and\s+)?(?:no|not)\s+(?:fewer|less)\s+than\s+\w+|,?\s*\bat\s+least\s+\w+\s+and\b",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': the larger number is within the range",
    ),
    (
        re.compile(r",?\s*\b(?:or\s+)?(?:maybe|perhaps|possibly)\s+(\d+|[a-z]+)\b", re.IGNORECASE),
        " ",
        "'{0}': used the first number",
    ),
    (
        re.compile(
            r",?\s*\b(?:but\s+)?not\s+(one|two|three|four|five|six|seven|eight|nine|ten)\b"
            r"(?!\s*(?:cm|mm|high|tall|long|wide|cubes?\s+(?:high|tall|long|wide)))",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': kept the other number",
    ),
    (
        re.compile(
            r",?\s*\b(?:with\s+)?(?:no|without)\s+(?:any\s+)?(?:windows|gaps|holes|openings)"
            r"(?:\s+(?:or|and)\s+(?:windows|gaps|holes|openings))*\b",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': solid, as built",
    ),
    (
        re.compile(
            r",?\s*\b(?:with\s*out|with\s+no|and\s+no|no)\s+(?:a\s+|any\s+)?(?:beam|bridge|lintel|"
            r"connection|link)s?\s+(?:between|across|joining|connecting)\s+them\b",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': left separate",
    ),
    (
        re.compile(
            r",?\s*\b(?:with\s*out|with\s+no|and\s+no|no)\s+(?:using\s+)?(?:a\s+|any\s+)?(?:beam|lintel|"
            r"plank)s?"
            r"(?:\s*,?\s*(?:just|only)\s+cubes)?\b",
            re.IGNORECASE,
        ),
        "{no_beams}",
        "'{0}': built of cubes only",
    ),
    (
        re.compile(
            r"\b(?:i\s+)?(?:do\s+not|dont)\s+want\s+(?:a|an|the|any)?\s*(?:"
            + _SHAPE_ALT
            + r")\b\s*[,;:.]*\s*(?:(?:i\s+)?(?:want|need|would\s+like)\s+)?"
            r"(?:just\s+|only\s+|but\s+)?",
            re.IGNORECASE,
        ),
        " ",
        "left out what is not wanted: '{0}'",
    ),
    (
        re.compile(r"\bnot\s+too\s+many\s+(steps|levels|layers|cubes|stairs)\b", re.IGNORECASE),
        " 3 {0} ",
        "read '{0}' as a few (3)",
    ),
    (
        re.compile(r"\b(pyramid|ziggurat)(\s+that\s+is|\s*,)?\s+not\s+flat\b", re.IGNORECASE),
        " 3-D {0} ",
        "read '{0}' as a 3-D pyramid",
    ),
    # dimensions
    (
        re.compile(
            r"\b(?:each|both|every)\s+(?:arm|leg|side|wing|branch)s?\s+(?:is\s+|are\s+)?(\d+|[a-z]+)"
            r"(?:\s+(?:cubes?|parts?|blocks?))?(?:\s+long)?",
            re.IGNORECASE,
        ),
        " {0} long and {0} wide ",
        "",
    ),
    (
        re.compile(r"\b(\d+|[a-z]+)\s+(?:down|along|up)\s+the\s+(stem|leg|arm|base|bar)\b", re.I),
        " {0} {1} ",
        "",
    ),
    (
        re.compile(
            r"\b(\d+|[a-z]+)\s+(?:columns|cols)\s+(?:by|x|and)\s+(\d+|[a-z]+)\s+rows\b", re.I
        ),
        " {0} by {1} ",
        "",
    ),
    (
        re.compile(r"\b(\d+|[a-z]+)\s+rows\s+(?:by|x)\s+(\d+|[a-z]+)\s+(?:columns|cols)\b", re.I),
        " {0} by {1} ",
        "",
    ),
    (
        re.compile(
            r"(?:^|(?<=[,.;:(]))\s*(wide|deep|high|tall|long)\s*[:=]?\s*(\d+)"
            r"(?:\s+(?:cubes?|parts?|blocks?))?\b",
            re.I,
        ),
        " {1} {0} ",
        "",
    ),
    (
        re.compile(r"\b(?:held\s+up|supported|carried|borne|propped\s+up)\s+by\b", re.IGNORECASE),
        " with ",
        "",
    ),
    (
        re.compile(
            r"\bin\s+(?:its\s+(?:courtyard|inside|interior|middle|centre|center)|the\s+"
            r"(?:courtyard|interior))\b(?!\s+of)",
            re.I,
        ),
        " inside ",
        "",
    ),
    (
        re.compile(
            r"\b(beside|next\s+to)\s+((?:a|an|the)\s+[\w\s-]{1,40}?)\s*,\s*on\s+(?:the\s+\w+'s|its)\s+"
            r"(left|right|front|back)(?:\s+side)?\b",
            re.IGNORECASE,
        ),
        " to the {2} of {1} ",
        "",
    ),
]
_REWRITES += [
    (
        re.compile(
            r"\b(\d+|[a-z]+)\s+(?:cubes?|parts?|blocks?)\s+(?:as|in|into|making|to\s+make)\s+"
            r"(two|three|four|five|six|\d+)\s+(?:equal\s+|identical\s+|even\s+)?"
            r"(towers|stacks|columns|piles|rows|walls)"
            r"(?:\s+of\s+(?:equal|the\s+same)\s+(?:height|size|length))?",
            re.IGNORECASE,
        ),
        "{split}",
        "",
    ),
    (
        re.compile(
            r"\b(double|triple|quadruple)[- ](?:height|decker|deck|layer|level|tier|storey)\b", re.I
        ),
        "{layers}",
        "read '{0}' as that many layers",
    ),
    (
        re.compile(
            r"\b(\d+|two|three|four|five)[- ](?:pillar|post|column|leg|pier)s?\s+(bridge|gate)\b",
            re.I,
        ),
        " {1} with {0} pillars ",
        "",
    ),
    (
        re.compile(
            r"\b(?:anywhere\s+)?(?:except|but|other\s+than|apart\s+from|away\s+from)\s+"
            r"(?:near|close\s+to|next\s+to)\s+(?:the\s+)?robot\b",
            re.IGNORECASE,
        ),
        " at the back ",
        "read '{0}' as at the back (far from the robot)",
    ),
]
_REWRITES += [
    (
        re.compile(
            r"\b(\d+|two|three|four|five|six|seven|eight|nine|ten)\s+single\s+(?=cubes|blocks)",
            re.IGNORECASE,
        ),
        " {0} separate ",
        "",
    ),
    (
        re.compile(
            r"\b(\d+|[a-z]+)\s+(?:cubes|parts|blocks)\s+in\s+(two|three|four|five|\d+)\s+rows\b",
            re.IGNORECASE,
        ),
        "{rows}",
        "",
    ),
    (
        re.compile(
            r"\bright\s+(?=(?:up|next|behind|in\s+front|in\s+the\s+(?:centre|center|middle)|beside|"
            r"against|at\s+the|by\s+the|over|"
            r"above|below|under|there|here|away|now)\b)",
            re.IGNORECASE,
        ),
        " ",
        "",
    ),
    (
        re.compile(
            r"\b(centred|centered)\s+(?:from\s+)?(?:left\s+to\s+right|side\s+to\s+side)", re.I
        ),
        " {0} ",
        "",
    ),
    (
        re.compile(r"\bwith\s+(?:a|an)\s+(\d+\s*x\s*\d+|\d+)\s+(?:bottom|footprint|foot)\b", re.I),
        " with a {0} base ",
        "",
    ),
    (
        re.compile(
            r",?\s*\b(?:but\s+)?(?:not\s+touching(?:\s+each\s+other)?|spaced\s+out|spread\s+out|"
            r"with\s+gaps?\s+between\s+them)\b",
            re.IGNORECASE,
        ),
        " spaced 5 cm apart ",
        "read '{0}' as a part's width apart",
    ),
    (re.compile(r"\b(left|right|front|back)\s+half\b", re.IGNORECASE), " {0} ", ""),
    (re.compile(r",?\s*\ball\s+touching(?:\s+each\s+other)?\b", re.IGNORECASE), " ", ""),
    (
        re.compile(
            r"\b(?:do\s+not|never)\s+(?:build|put|place)\s+anything\s+(?:at|on|in)\s+the\s+"
            r"(?:left|right|front|back)(?:\s+side)?\b\s*[;,.]?",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': nothing is built there",
    ),
    (
        re.compile(
            r",?\s*\b(?:and\s+)?(?:no|not)\s+(?:shorter|lower|smaller)\s+than\s+\w+(?:\s+cubes?)?",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': the larger number is within the range",
    ),
    (
        re.compile(r",?\s*\bneither\s+(?:one\s+)?touching\s+the\s+other\b", re.IGNORECASE),
        " spaced 5 cm apart ",
        "read '{0}' as a part's width apart",
    ),
    (
        re.compile(
            r"\b(square|rectangle|ring|grid)\b(\s+of\s+cubes)?\s*,?\s*hollow\b", re.IGNORECASE
        ),
        " hollow {0}{1} ",
        "",
    ),
    (re.compile(r",?\s*\bnot\s+filled(?:\s+in)?\b", re.IGNORECASE), " ", ""),
    (re.compile(r"\b(?:underneath|beneath|below)\s*(?=[,;.]|$)", re.IGNORECASE), " ", ""),
    (
        re.compile(
            r"\b(?:stacked\s+|resting\s+|standing\s+|sitting\s+)?(?:on|at)\s+(?:top\s+of\s+)?(?:each|both|"
            r"either|one|every)\s+(?:of\s+(?:its|the)\s+)?(?:end|ends|side|sides|corner|corners)"
            r"(?:\s+of\s+(?:it|them|the\s+\w+))?",
            re.IGNORECASE,
        ),
        "{placement}",
        "",
    ),
    (
        re.compile(
            r"\b(\d+|one|two|three|four|five)\s+(more|less|fewer)\s+(?:cubes?\s+|parts?\s+)?than\s+"
            r"(\d+|[a-z]+)\b",
            re.IGNORECASE,
        ),
        "{arith}",
        "",
    ),
    (
        re.compile(
            r"\b(\d+|two|three|four|five)\s+more\s+(?:just\s+)?(?:like|of)\s+(?:it|them|that|those)\b",
            re.IGNORECASE,
        ),
        "{more_like}",
        "",
    ),
    (
        re.compile(
            r"\bnear\s+(?:to\s+)?the\s+(back|front|left|right)(?:\s+(?:edge|side|end|wall))?\b",
            re.I,
        ),
        " at the {0} ",
        "",
    ),
    (re.compile(r",?\s*\bnear\s+the\s+edge\b", re.IGNORECASE), " ", ""),
    (
        re.compile(
            r"\balong\s+the\s+(left|right)\s+(?:edge|side|boundary|border)\b", re.IGNORECASE
        ),
        " along x on the {0} ",
        "",
    ),
    (
        re.compile(
            r"\balong\s+the\s+(front|back)\s+(?:edge|side|boundary|border)\b", re.IGNORECASE
        ),
        " along y at the {0} ",
        "",
    ),
    (
        re.compile(r"\b(towers|rows|walls|stacks|columns|pyramids|pads)\s*[:=]\s*(\w+)\b", re.I),
        " {1} {0} ",
        "",
    ),
    (re.compile(r"\bheight\s*[:=]\s*(\d+)", re.IGNORECASE), " {0} high ", ""),
    (
        re.compile(
            r",?\s*\b(?:none\s+of\s+(?:them|the\s+\w+)|no\s+\w+|not|never)\s+(?:any\s+)?(?:wider|broader)\s+"
            r"than\s+(\w+)\s+(?:cubes?|parts?)\b",
            re.IGNORECASE,
        ),
        " {0} wide ",
        "read '{0}' as exactly that (the most allowed)",
    ),
    (re.compile(r"\b(?:length|long)\s*[:=]\s*(\d+)", re.IGNORECASE), " {0} long ", ""),
    (re.compile(r"\bwidth\s*[:=]\s*(\d+)", re.IGNORECASE), " {0} wide ", ""),
    (
        re.compile(
            r"\b(\d+|two|three|four|five)\s+rows\s+(?:with|of)\s+(\d+|[a-z]+)\s+(?:cubes?\s+)?"
            r"(?:in\s+each|each|apiece)\b",
            re.IGNORECASE,
        ),
        "{rows_of}",
        "",
    ),
    (
        re.compile(r"\bon\s+top\s+off\b", re.IGNORECASE),
        " on top of ",
        "corrected 'top off' to 'top of'",
    ),
    (
        re.compile(
            r"\b(?:that\s+|which\s+)?(?:do|does)\s+not\s+touch(?:\s+each\s+other)?\b", re.IGNORECASE
        ),
        " spaced 5 cm apart ",
        "read '{0}' as a part's width apart",
    ),
    (
        re.compile(
            r"\b(?:but\s+)?(?:do\s+not|never)\s+(?:put|place|build|set)\s+(?:it|them)\s+(?:near|close\s+to|"
            r"next\s+to)\s+(?:the\s+)?robot\b",
            re.IGNORECASE,
        ),
        " at the back ",
        "read '{0}' as at the back (far from the robot)",
    ),
    (
        re.compile(
            r",?\s*\b(?:but\s+)?not\s+an?\s+(?:l|u|t|"
            + _SHAPE_ALT
            + r")(?:[- ]shape[d]?)?\s*(?=$|[,.;:!])",
            re.IGNORECASE,
        ),
        " ",
        "left out what is not wanted: '{0}'",
    ),
    (
        re.compile(r"\b(?:actually|sorry|oops|wait)\s*,?\s*(?:no\s*,?)?", re.IGNORECASE),
        " then ",
        "",
    ),
    (
        re.compile(r",?\s*\bnothing\s+(?:big|large|huge|tall|fancy|special)\b", re.IGNORECASE),
        " ",
        "",
    ),
    (
        re.compile(
            r"\b(twice|double|three\s+times|thrice|half)\s+as\s+(tall|high|long|wide)\s+as\s+(?:a\s+)?"
            r"(\d+|[a-z]+)(?:[- ](?:cubes?|parts?|blocks?)(?:[- ](?:tower|stack|column|one))?)?\b",
            re.IGNORECASE,
        ),
        "{times}",
        "",
    ),
    (
        re.compile(
            r"\b(\d+|[a-z]+)\s+(?:cubes?|parts?)\s+(?:per|in\s+each|each|a)\s+(?:course|level|layer|row|tier)\b",
            re.IGNORECASE,
        ),
        " {0} long ",
        "",
    ),
    (
        re.compile(r"(?<!by\s)\b(\d+(?:\.\d+)?\s*(?:cm|mm|m))\s+square\b", re.IGNORECASE),
        " {0} by {0} ",
        "",
    ),
    (
        re.compile(r"\b(steps|levels|layers|storeys|floors|tiers|spans)\s*[:=]\s*(\d+)\b", re.I),
        " {1} {0} ",
        "",
    ),
    (re.compile(r"\b(?:shape|structure|type|kind)\s*[:=]\s*", re.IGNORECASE), " a ", ""),
]
_OPEN = re.compile(
    r"\b(?:(tall|high|big|large)\s+)?(structure|thing|something|shape|construction|object|"
    r"build|sculpture|monument)\s+(?:that\s+is\s+\w+\s+)?with\s+a\s+(wide|broad|big|large|"
    r"wider|broader|heavy|solid)\s+(base|bottom|foot|footing|foundation)\b",
    re.IGNORECASE,
)


@dataclass
class _Phrase:
    """A noun phrase that names one or more structures (or refers to earlier ones)."""

    tokens: list[int]
    clause: int
    text: str = ""
    spec: Spec | None = None
    first: int = 0  # index of its first structure in the reading
    count: int = 0  # how many structures it produced
    ref: int | None = None  # a pure reference: the phrase it refers to
    side: str | None = None  # "it on the right": the side the reference names
    modified: bool = False  # "then add two more cubes to it": changed an earlier structure
    structure: int | None = None  # "the first one", "the smaller one": which structure
    unused: list[str] = field(default_factory=list)


@dataclass
class _Rel:
    kind: str
    subject: int  # phrase index
    object: int | None  # phrase index; None: "on top" with no object (the phrase before)
    side: str | None = None


@dataclass
class _State:
    command: str
    cell: CellConfig
    notes: list[str] = field(default_factory=list)
    ignored: list[str] = field(default_factory=list)
    material: list[str] = field(default_factory=list)
    no_stack: bool = False
    no_beams: bool = False


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
    st = _State(command, cell)
    text = _normalise(command, st.notes)
    text, corrected = typos.correct(text)
    st.notes += corrected
    text = _rewrite(text, st)
    text = text.strip()
    doc = parse(text)
    phrases, rels = _structure(doc)
    structures = _fill(phrases, rels, st, doc)
    if not structures:
        # nothing recognised: correct harder (words the English vocabulary knows too, "wal"),
        # then read a structure-less description ("something small") as a tower
        retry, fixed = typos.correct(text, aggressive=True)
        if not fixed:
            retry, fixed = _open(text)
        if fixed:
            st = _State(command, cell, notes=st.notes + fixed)
            text = retry
            doc = parse(text)
            phrases, rels = _structure(doc)
            structures = _fill(phrases, rels, st, doc)
    if not structures:
        _no_structure(st, doc, command)
    relations, structures = _relate(phrases, rels, structures, st)
    structures = [check_family(s, st.notes, st.material, part_m=cell.cube[0]) for s in structures]
    if st.no_stack:
        structures = [_unstack(s, st) for s in structures]
    if st.no_beams:
        for s in structures:
            if s.shape in ("bridge", "arch", "canopy") or s.part == "beam":
                st.material.append("no beams")
                st.notes.append(f"ignored 'no beams': a {s.shape} here is built with beams")
    if len(structures) > 50:
        raise SpecError(
            f"{len(structures)} structures is more than 50", understood=_understood(doc)
        )
    try:
        spec = Spec(
            structures=tuple(structures),
            relations=tuple(relations),
            notes=tuple(dict.fromkeys(st.notes)),
        )
    except ValueError as exc:
        raise SpecError(
            f"the structures cannot be related: {exc}", understood=_understood(doc)
        ) from None
    return Reading(
        command=command,
        text=text.strip(),
        spec=spec,
        phrases=tuple(p.text for p in phrases if p.text and p.ref is None),
        notes=tuple(dict.fromkeys(st.notes)),
        ignored=tuple(dict.fromkeys(st.ignored)),
        material=tuple(dict.fromkeys(st.material)),
    )


# -- 1. normalise ---------------------------------------------------------------------------
_CONTRACTIONS = [
    (re.compile(r"\b(can)'?t\b", re.IGNORECASE), r"\1 not"),
    (re.compile(r"\bwon'?t\b", re.IGNORECASE), "will not"),
    (re.compile(r"\b(is|are|was|were|do|does|did|should|must|could|would)n'?t\b", re.I), r"\1 not"),
]


_SCIENTIFIC = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?|\.\d+)[eE]([+-]?\d+)\b")
_NOT_A_NUMBER = re.compile(r"(?<![\w])(nan|inf|infinity)(?![\w])", re.IGNORECASE)
_DECIMAL_COMMA = re.compile(r"(?<=[=:])\s*(-?\d+),(\d+)\b(?!\s*(?:,|and)\s*\d)")
_REFERENCE_NO = re.compile(
    r"(?:#|\bno\.\s*|\bnumber\s+)\d+\b|\b(?:order|ticket|job|ref|request|id|station|cell)\s*"
    r"[:#]?\s*[A-Za-z]*\d[\w-]*|\b\d{3,}-\d+\b",
    re.IGNORECASE,
)
_METRE_WORDS = [
    (re.compile(r"\bhalf\s+a\s+(metre|meter)\b", re.I), "0.5 m"),
    (re.compile(r"\b(?:a\s+)?quarter\s+(?:of\s+)?a\s+(metre|meter)\b", re.I), "0.25 m"),
    (re.compile(r"\ba\s+(metre|meter)\b", re.I), "1 m"),
]
_LIST_ITEM = re.compile(
    r"(?:^|\n|(?<=[.;]))\s*\d+\)\s+(?=[A-Za-z])|(?:^|\n)\s*\d+\.\s+(?=[A-Za-z])"
)
_BULLET = re.compile(r"(?:^|\n)\s*[-*•]\s+(?=[A-Za-z0-9])")
_ROBOT_NAME = re.compile(r"\b(?:the\s+)?(?:abb\s+)?irb\s*-?\s*(?:120|1600)\b", re.IGNORECASE)
_PAIR_UNIT = re.compile(
    r"\(\s*(-?\d+(?:\.\d+)?)\s*,\s*(-?\d+(?:\.\d+)?)\s*\)\s*(mm|cm|m)\b", re.IGNORECASE
)
_SLASH_XY = re.compile(
    r"\b(\d+(?:\.\d+)?)\s*/\s*(\d+(?:\.\d+)?)\s*(mm|cm|m)\b(?:\s*\(\s*x\s*/\s*y\s*\))?",
    re.IGNORECASE,
)
_COUNTED = r"(?:towers|stacks|rows|walls|cubes|blocks|pillars|columns|more|steps|levels|layers)"
_HOMOPHONES = [
    (re.compile(r"\b(?:to|too)\s+(?=" + _COUNTED + r"\b|by\s+(?:to|too|two|\d))", re.I), "two "),
    (re.compile(r"(?<=\bby\s)(?:to|too)\b", re.I), "two"),
    (re.compile(r"\bfor\s+(?=" + _COUNTED + r"\b|high\b|tall\b|long\b|wide\b)", re.I), "four "),
    (re.compile(r"(?<=\bof\s)for\s*$", re.I), "four"),
    (re.compile(r"\bate\s+(?=" + _COUNTED + r"\b)", re.I), "eight "),
    (re.compile(r"(?<=\d)\s+bye\s+(?=\d)", re.I), " by "),
    (re.compile(r"\b(?:el|ell)\s+(?=shape|shaped)", re.I), "L "),
    (re.compile(r"\btee\s+(?=shape|shaped)", re.I), "T "),
]
_AXES_LABEL = re.compile(
    r"\(\s*(?:length|width|height|depth|[lwdh])(?:\s*[x×*,/]\s*(?:length|width|height|depth|"
    r"[lwdh]))+\s*\)|\b[lwdh]\s*[x×*]\s*[lwdh](?:\s*[x×*]\s*[lwdh])?\s*[=:]",
    re.IGNORECASE,
)
_SUM = re.compile(r"\b(\d+)\s*\+\s*(\d+)\b")
_SLASHES = re.compile(r"\b\d+(?:/\d+)+\b(?!\s*(?:mm|cm|m)\b)")
# The largest number a command may carry; beyond it nothing SDI builds is meant.
_LARGEST = 1e6


def _normalise(command: str, notes: list[str] | None = None) -> str:
    """Symbols, contractions, number forms. Numbers SDI cannot use are refused here."""
    notes = notes if notes is not None else []
    text = command
    for a, b in _SYMBOLS.items():
        text = text.replace(a, b)
    text = text.replace("@", " at ")
    text = re.sub(r"\bontop\b", "on top", text, flags=re.IGNORECASE)

    # an aside in parentheses belongs to the noun before it: "the wall (3 long, 2 high)"
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

    def reference(m: re.Match[str]) -> str:
        notes.append(f"ignored '{m.group(0)}': a reference number, not a size")
        return " "

    text = _REFERENCE_NO.sub(reference, text)
    for pattern, repl in _METRE_WORDS:
        text = pattern.sub(repl, text)
    for m in re.finditer(r"\d+(?:\.\d+)?", text):
        if float(m.group(0)) > _LARGEST:
            raise SpecError(
                f"{m.group(0)} is too large for any count or position in the cell; "
                f"numbers above {_LARGEST:g} are refused",
                understood={"numbers": [m.group(0)]},
            )
    text = _LIST_ITEM.sub(" then ", text)  # "1) a tower\n2) another one …"
    text = _BULLET.sub(" , ", text)  # "- tower / - 4 cubes / - left side": one thing's details
    text = _ROBOT_NAME.sub(" the robot ", text)
    text = _PAIR_UNIT.sub(lambda m: f"({m.group(1)} {m.group(3)}, {m.group(2)} {m.group(3)})", text)
    text = _SLASH_XY.sub(
        lambda m: f"x = {m.group(1)} {m.group(3)}, y = {m.group(2)} {m.group(3)}", text
    )
    for pattern, repl in _HOMOPHONES:
        text = pattern.sub(repl, text)
    text = _AXES_LABEL.sub(" ", text)  # "W×D×H = 3×2×2", "(length x height)"
    text = re.sub(
        r"\b([LHW])\s*=\s*(\d+(?:\.\d+)?)\s*(mm|cm|m|cubes?)?",
        lambda m: (
            f" {m.group(2)} {m.group(3) or ''} "
            + {"L": "long", "H": "high", "W": "wide"}[m.group(1).upper()]
            + " "
        ),
        text,
        flags=re.IGNORECASE,
    )

    def plus(m: re.Match[str]) -> str:
        total = int(m.group(1)) + int(m.group(2))
        notes.append(f"read '{m.group(0)}' as {total}")
        return str(total)

    text = _SUM.sub(plus, text)
    text = _SLASHES.sub(lambda m: ", ".join(m.group(0).split("/")[:-1]) + " and " +
                        m.group(0).split("/")[-1], text)  # fmt: skip
    text = _DIMS.sub(" x ", text)
    return _SPACES.sub(" ", text).strip()


_ANOTHER = re.compile(
    r"\b(?:(?:another|one\s+more|a\s+second|a\s+third|a\s+fourth)\s+(?:identical\s+|similar\s+|"
    r"matching\s+)?one\b|a\s+(?:third|fourth|fifth)\b"
    r"(?!\s+(?:as|of|level|layer|tier|row|storey))|(?<=,\s)one(?=\s+(?:on|at|in|to)\s+the\b)|"
    r"(?<=\band\s)one(?=\s+(?:on|at|in|to)\s+the\b))",
    re.IGNORECASE,
)
_SIZES = ("count", "length", "width", "height", "steps", "span", "spans", "dims",
          "length_m", "width_m", "height_m", "gap_m", "part")  # fmt: skip
_N = r"(\d+|a|an|one|two|three|four|five|six|seven|eight|nine|ten|another|one\s+more)"
_UNIT = (
    r"(?:\s+(?:more|extra|additional|further))?"
    r"(?:\s+(?:cubes?|levels?|layers?|parts?|blocks?|steps?|storeys?|tiers?))?"
)
_REF = r"(?:it|them|the\s+\w+(?:\s+one)?)"


def _op(pattern: str, op: str) -> tuple[re.Pattern[str], str]:
    return re.compile(pattern, re.IGNORECASE), op


# (pattern, operation on the height of the structure referred to)
_MODIFY = [
    _op(r"\b(?:add|put|stack|place|pile)\s+" + _N + r"\s+(?:more|extra|additional)" + _UNIT, "+"),
    _op(r"\b(?:add|put|stack|place)\s+" + _N + _UNIT + r"\s+(?:to|on|onto)\s+" + _REF + r"\b", "+"),
    _op(
        r"\badd\s+(?:a|one|another)\s+(?:second|third|fourth|fifth|new|further|extra|more)?"
        r"\s*(?:layer|level|tier|storey|course)\b",
        "+1",
    ),
    _op(
        r"\bmake\s+(?:it|them)\s+" + _N + r"\s+(?:more\s+)?(?:cubes?\s+|levels?\s+|layers?\s+)?"
        r"(?:taller|higher)\b",
        "+",
    ),
    _op(r"\b(?:raise|extend|grow)\s+(?:it|them)\s+by\s+" + _N + _UNIT, "+"),
    _op(
        r"\b(?:keep\s+adding|add)\s+(?:steps|levels|layers|cubes)\s+until\s+(?:it|there)\s+"
        r"(?:has|is|are)\s+" + _N,
        "=",
    ),
    _op(r"\b(?:build|raise|stack|grow)\s+(?:it|them)\s+up\s+to\s+" + _N, "="),
    _op(r"\bmake\s+(?:it|them)\s+" + _N + r"\s*(?:instead)?\s*$", "="),
    _op(
        r"\b(?:move|shift|put|place|slide)\s+(?:it|them)\s+(?:over\s+)?(?:to|towards|into|at|on)\s+(?:the\s+)?"
        r"(left|right|front|back|middle|centre|center)\b",
        "region",
    ),
    _op(
        r"\buntil\s+(?:it|they)\s+(?:is|are|stands?)\s+"
        + _N
        + r"\s+(?:cubes?\s+|levels?\s+|layers?\s+)?(?:high|tall)\b",
        "=",
    ),
    _op(r"\b(?:make\s+(?:it|them)\s+)?" + _N + r"\s+times\s+as\s+(?:tall|high)\b", "*"),
    _op(r"\b(double|triple)\s+(?:its|their|the)\s+height\b", "*"),
    _op(r"\b(double|triple)\s+(?:it|them)\s+in\s+height\b", "*"),
    _op(r"\b(?:take|knock|lift)\s+(?:away|off)\s+" + _N + r"\s+(?:cubes?|levels?|layers?)\b", "-"),
    _op(
        r"\b(?:take|knock|lift)\s+off\s+(?:its|the)\s+top\s+(?:row|level|layer|course|tier)\b", "-1"
    ),
    _op(r"\b(?:cut|chop)\s+(?:it|them)\s+in\s+(half)\b|\bhalve\s+(?:it|them)\b", "/"),
    _op(
        r"\bmake\s+(?:it|them|the\s+\w+)\s+"
        + _N
        + r"\s+(?:steps|cubes?\s+(?:high|tall)|levels?|layers?|high|tall|storeys?)\b",
        "=",
    ),
    _op(
        r"\b(?:take|knock|lift|remove)\s+"
        + _N
        + r"\s+(?:cubes?\s+|levels?\s+)?(?:back\s+)?(?:off|away|from\s+the\s+top)\b",
        "-",
    ),
    _op(
        r"\b(?:take|knock|lift)\s+(?:off\s+)?(?:the\s+)?top\s+"
        + _N
        + r"?\s*(?:cubes?\s+|levels?\s+)?off\b",
        "-",
    ),
    _op(
        r"\b(?:take|knock|lift|remove)\s+(?:off\s+)?the\s+top\s+(cube|one|level|layer)\b"
        r"(?:\s+off)?",
        "-1",
    ),
]
_REMOVAL = re.compile(
    r"^(?:\w+\s+){0,2}?(?:take|takes|pull|pulls|remove|removes|push|pushes|move|moves|shift|"
    r"slide|swap|delete|knock|cut|subtract|shove|merge|join\s+up)\b"
    r"(?!.*\b(?:tower|wall|row|pyramid|staircase|bridge|grid|block|ring|castle|arch)s?\b.*\b"
    r"(?:of|with)\s+\d)",
    re.IGNORECASE,
)
_COUNT_ONLY = re.compile(
    r"^\W*(?:\d+|[a-z]+)\s+(?:cubes?|parts?|blocks?)(?:\s+(?:tall|high|long))?\W*$", re.I
)
_LEGS = re.compile(r"\blegs?\b", re.IGNORECASE)
_TOP = re.compile(r"\b(?:top|roof|tabletop|surface|lid)\b", re.IGNORECASE)


def _another(text: str) -> str:
    """ "a tower on the left and another one on the right": another tower."""

    def sub(m: re.Match[str]) -> str:
        before = [
            w
            for w in re.findall(r"[a-z]+", text[: m.start()].lower())
            if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES
        ]
        if not before:
            return m.group(0)
        noun = before[-1]
        noun = noun[:-1] if noun.endswith("s") and noun[:-1] in lx.SHAPE_WORDS else noun
        return f"another {noun}"

    return _ANOTHER.sub(sub, text)


def _copies(spec: Spec, text: str, st: _State, earlier: list[StructureSpec] | None = None) -> Spec:
    """ "another tower", "a second row": the sizes of the one named before (in this phrase,
    or the last of that family named earlier)."""
    if not set(re.findall(r"[a-z]+", text.lower())) & _COPY:
        return spec
    out = list(spec.structures)
    for k, s in enumerate(out):
        if s.model_dump(include=set(_SIZES), exclude_defaults=True):
            continue
        pool = [*(earlier or []), *out[:k]]
        first = next((o for o in reversed(pool) if o.shape == s.shape), None)
        if k == 0 and first is None:
            continue
        if first is not None:
            out[k] = s.model_copy(update=first.model_dump(include=set(_SIZES)))
            st.notes.append(f"another {s.shape}: the same size as the first")
    return spec.model_copy(update={"structures": tuple(out)})


def _modify(p: _Phrase, before: list[_Phrase], structures: list[StructureSpec], st: _State) -> bool:
    """ "then add two more cubes to it", "make it two taller": change an earlier structure."""
    built = [q for q in before if q.spec is not None and q.count]
    if not built:
        return False
    for pattern, op in _MODIFY:
        m = pattern.search(p.text)
        if not m:
            continue
        if op == "region":
            place = m.group(1).lower()
            place = {"middle": "centre", "center": "centre"}.get(place, place)
            target = built[-1]
            index = target.first + target.count - 1
            structures[index] = structures[index].model_copy(
                update={"region": place, "at_x": None, "at_y": None}
            )
            st.notes.append(f"'{m.group(0).strip()}': the {structures[index].shape} goes {place}")
            p.count = 0
            p.modified = True
            return True
        if op in ("+1", "-1"):
            n, op = 1, op[0]
        else:
            word = re.sub(r"\s+", " ", (m.group(1) or ("2" if op == "/" else "1")).lower())
            word = {"another": "1", "one more": "1", "a": "1", "an": "1", "double": "2",
                    "triple": "3", "half": "2"}.get(word, word)  # fmt: skip
            value = words_to_numbers([word])[0]
            if not value.isdigit():
                return False
            n = int(value)
        target = built[-1]
        index = target.first + target.count - 1
        ordinal = re.search(r"\bthe\s+(first|second|third|last)\b", p.text, re.I)
        if ordinal and target.count > 1:
            pick = {"first": 0, "second": 1, "third": 2, "last": target.count - 1}
            index = target.first + min(pick[ordinal.group(1).lower()], target.count - 1)
        last = structures[index]
        key = "steps" if last.shape == "staircase" else "height"
        now = getattr(last, key) or (1 if last.shape in ("grid", "row", "enclosure") else 3)
        if op == "/" and now % n:
            return False
        new = {"+": now + n, "-": now - n, "=": n, "*": now * n, "/": now // n}[op]
        if new < 1:
            return False
        shape = last.shape
        if key == "height" and new > 1 and shape in ("grid", "row"):
            shape = "block" if shape == "grid" else "wall"
        structures[index] = last.model_copy(update={key: new, "shape": shape})
        st.notes.append(f"'{m.group(0).strip()}': the {last.shape} now has {key} {new}")
        p.count = 0
        p.modified = True
        return True
    return False


def _split(m: re.Match[str], st: _State) -> str:
    """ "twelve cubes in three equal stacks": three stacks of four."""
    said = [words_to_numbers([g.lower()])[0] for g in (m.group(1), m.group(2))]
    if not all(v.isdigit() for v in said):
        return m.group(0)
    total, count = int(said[0]), int(said[1])
    noun = m.group(3).lower()
    if count < 1 or total % count:
        st.material.append(m.group(0))
        st.notes.append(f"ignored '{m.group(0)}': {total} parts do not split into {count} equal")
        return f" {count} {noun} "
    st.notes.append(f"{total} parts as {count} {noun}: {total // count} each")
    return f" {count} {noun} of {total // count} cubes "


Handler = Callable[[re.Match[str], _State, str], str]


def _said(m: re.Match[str]) -> tuple[str, list[str]]:
    return m.group(0).strip(" ,"), [g.lower() if g else "" for g in m.groups()]


def _no_stack(m: re.Match[str], st: _State, note: str) -> str:
    st.no_stack = True
    st.notes.append(note.format(_said(m)[0]))
    return " "


def _no_beams(m: re.Match[str], st: _State, note: str) -> str:
    st.no_beams = True
    st.notes.append(note.format(_said(m)[0]))
    return " "


def _placement(m: re.Match[str], st: _State, note: str) -> str:
    if re.search(r"\b(?:castle|fort|fortress|citadel)s?\b", m.string, re.IGNORECASE):
        return m.group(0)  # "a castle with a tower at each corner": the family's own
    if re.search(r"\d+\s*(?:cubes?|parts?|blocks?)?\s*(?:long\s*)?$", m.string[: m.start()]):
        return m.group(0)  # "a courtyard 5 cubes on each side": a size
    said = _said(m)[0]
    st.material.append(said)
    st.notes.append(
        f"ignored '{said}': parts cannot be placed on a chosen end, side or corner of a "
        "structure yet"
    )
    return " "


def _arith(m: re.Match[str], st: _State, note: str) -> str:
    said, groups = _said(m)
    a_, b_ = (words_to_numbers([g])[0] for g in (groups[0], groups[2]))
    if not (a_.isdigit() and b_.isdigit()):
        return m.group(0)
    value = int(b_) + (int(a_) if groups[1] == "more" else -int(a_))
    st.notes.append(f"read '{said}' as {value}")
    return f" {value} "


def _more_like(m: re.Match[str], st: _State, note: str) -> str:
    shapes = [w for w in re.findall(r"[a-z]+", m.string[: m.start()].lower())
              if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES]  # fmt: skip
    if not shapes:
        return m.group(0)
    noun = shapes[-1] if shapes[-1].endswith("s") else shapes[-1] + "s"
    return f" {_said(m)[1][0]} identical {noun} "


def _times(m: re.Match[str], st: _State, note: str) -> str:
    said, groups = _said(m)
    factor = {"twice": 2, "double": 2, "three times": 3, "thrice": 3, "half": 0.5}
    base_n = words_to_numbers([groups[2]])[0]
    k_ = factor.get(re.sub(r"\s+", " ", groups[0]), 0)
    if not base_n.isdigit() or not k_ or (int(base_n) * k_) % 1:
        return m.group(0)
    value = int(int(base_n) * k_)
    st.notes.append(f"read '{said}' as {value} {groups[1]}")
    return f" {value} {groups[1]} "


def _climb(m: re.Match[str], st: _State, note: str) -> str:
    # a staircase climbs towards +x along x and +y along y (left = +y, back = +x)
    return {
        "back": " along x ",
        "left": " along y ",
        "front": " along x rotated 180 degrees ",
        "right": " along y rotated 180 degrees ",
    }[_said(m)[1][0]]


def _rows(m: re.Match[str], st: _State, note: str) -> str:
    said_n = [words_to_numbers([g])[0] for g in _said(m)[1][:2]]
    if all(v.isdigit() for v in said_n) and int(said_n[0]) % int(said_n[1]) == 0:
        return f" {int(said_n[0]) // int(said_n[1])} by {said_n[1]} "
    return m.group(0)


def _rows_of(m: re.Match[str], st: _State, note: str) -> str:
    groups = _said(m)[1]
    walls = re.search(r"\b(?:wall|walls|fence)\b", m.string[: m.start()], re.IGNORECASE)
    return f" {groups[0]} {'levels' if walls else 'rows'} of {groups[1]} "


def _layers(m: re.Match[str], st: _State, note: str) -> str:
    said, groups = _said(m)
    st.notes.append(note.format(said))
    layers = {"double": 2, "triple": 3, "quadruple": 4}[groups[0]]
    return f"{layers}-layer"


# Rewrites whose replacement is computed: the `_REWRITES` entry names one of these.
_HANDLERS: dict[str, Handler] = {
    "{split}": lambda m, st, note: _split(m, st),
    "{no_stack}": _no_stack,
    "{no_beams}": _no_beams,
    "{placement}": _placement,
    "{arith}": _arith,
    "{more_like}": _more_like,
    "{times}": _times,
    "{climb}": _climb,
    "{rows}": _rows,
    "{rows_of}": _rows_of,
    "{layers}": _layers,
}


def _rewrite(text: str, st: _State) -> str:
    text = _another(text)
    if (
        _LEGS.search(text)
        and _TOP.search(text)
        and not any(
            lx.SHAPE_WORDS.get(w) in ("canopy", "bridge", "arch")
            for w in re.findall(r"[a-z]+", text.lower())
        )
    ):
        st.notes.append("legs with a top: read as a table")
        text = "a table with " + text
    for pattern, replacement, note in _REWRITES:

        def sub(m: re.Match[str], replacement: str = replacement, note: str = note) -> str:
            handler = _HANDLERS.get(replacement)
            if handler is not None:
                return handler(m, st, note)
            said = m.group(0).strip(" ,")
            groups = [g.lower() if g else "" for g in m.groups()]
            opposite = _OPPOSITE.get(groups[0], "") if groups else ""
            opposite2 = _OPPOSITE.get(groups[1], "") if len(groups) > 1 else ""
            if opposite2 and opposite2 in ("left", "right") and opposite in ("front", "back"):
                opposite, opposite2 = opposite2, opposite
            if note:
                st.notes.append(
                    _SPACES.sub(" ", note.format(said, opposite=opposite, opposite2=opposite2))
                )
            return replacement.format(*groups, "", "", opposite=opposite, opposite2=opposite2)

        text = pattern.sub(sub, text)
    text = _LEVEL_ORDINAL.sub(" on top ", text)
    m = _OPEN.search(text)
    if m and not any(w in lx.SHAPE_WORDS for w in re.findall(r"[a-z]+", text.lower())
                     if w not in ("base", "bottom") and w not in lx.AMBIGUOUS_SHAPES):  # fmt: skip
        size = "big " if m.group(1) else ""
        st.notes.append(
            f"read '{m.group(0)}' as a {size}3-D pyramid (wide at the base, rising to a point)"
        )
        text = text[: m.start()] + f"{size}3-D pyramid" + text[m.end() :]
    return _SPACES.sub(" ", text)


# -- 3–4. clauses, phrases and relation markers ---------------------------------------------
def _clauses(doc: Doc) -> list[tuple[list[int], bool]]:
    """The command's clauses (token indices), each with whether a sequence word ("then",
    "finally", a step label) introduced it."""
    # Clauses end at sentence punctuation, not at the parser's sentence guesses (it splits
    # "a tower at x = 450 mm" at "=").
    clauses: list[list[int]] = []
    current: list[int] = []
    for tok in doc:
        w = tok.lower_
        spaced_dash = (
            w in ("-", "--") and tok.i > 0 and doc[tok.i - 1].whitespace_ and tok.whitespace_
        )
        if spaced_dash and any(doc[i].lower_ in lx.SHAPE_WORDS for i in current):
            spaced_dash = False  # "a table - four legs and a flat top": the same structure
        if (
            (w in (";", ".", "!", "?") or spaced_dash)
            and tok.i != len(doc) - 1
            and not tok.like_num
        ):
            if current:
                clauses.append(current)
                current = []
            continue
        if w in _SEQUENCE and _starts_clause(doc, tok) and current:
            clauses.append(current)
            current = []
        current.append(tok.i)
    if current:
        clauses.append(current)
    # strip leading sequence words and trailing punctuation
    out: list[tuple[list[int], bool]] = []
    for c in clauses:
        sequenced = bool(c) and doc[c[0]].lower_ in _SEQUENCE | {"then", "finally", "lastly"}
        while c and doc[c[0]].lower_ in _LEADS | _SEQUENCE:
            c = c[1:]
        while c and doc[c[-1]].is_punct:
            c = c[:-1]
        if c:
            out.append((c, sequenced))
    return out


def _starts_clause(doc: Doc, tok: Token) -> bool:
    """`tok` ("then", "next", "after") begins a new step of the description."""
    w = tok.lower_
    if w == "next":
        nxt = doc[tok.i + 1].lower_ if tok.i + 1 < len(doc) else ""
        return nxt in (",", "add", "put", "place", "build", "stack", "make", "lay")
    if w == "after":
        nxt = doc[tok.i + 1].lower_ if tok.i + 1 < len(doc) else ""
        return nxt in ("that", "this")
    return True


_ONE = {"a", "an", "one", "single", "lone"}
_SPACES_WORDS = {"space", "hole", "gap", "room", "opening", "void", "cavity", "interior", "area"}


def _names_structure(doc: Doc, tokens: list[int]) -> bool:
    """The tokens name a structure (not a space: "a 2 by 2 space inside")."""
    if any(doc[i].lower_ in _SPACES_WORDS | _EMPTY for i in tokens):
        return False
    return any(_is_structure_noun(doc, i) for i in tokens)


def _is_structure_noun(doc: Doc, k: int) -> bool:
    w = doc[k].lower_
    if w in ("cube", "block", "brick", "box") and doc[k - 1].lower_ in _ONE and k > 0:
        return True  # "around a single cube": one part is a structure too
    if w in ("cubes", "blocks", "bricks") and any(
        doc[j].lower_ in ("pair", "couple", "both", "single", "separate", "individual", "loose")
        for j in range(max(0, k - 4), k)
    ):
        return True  # "a beam across a pair of single cubes": the cubes stand as pillars
    if w in lx.PART_WORDS and w not in ("block", "blocks"):
        return False
    if w in ("shape", "shaped") and k > 0 and doc[k - 1].lower_ in ("l", "u", "t", "plus", "cross"):
        return True  # "a U shape"
    if w in lx.LETTER_SHAPES and k + 1 < len(doc) and doc[k + 1].lower_ in lx.LETTER_SHAPE_TAILS:
        return True
    return w in lx.SHAPE_WORDS or w in _GENERIC or w in _BEAMS


def _object_head(doc: Doc, start: int, end: int, strong: bool = True) -> tuple[int | None, bool]:
    """The noun a relation marker points at, and whether it names a structure (`strong`:
    the marker is "on top of", after which "the base" is a structure too)."""
    k = start
    empty = False
    while k < end:
        tok = doc[k]
        w = tok.lower_
        if w in _EMPTY:
            empty = True
        if (w in _PRONOUNS or w in _ORDINALS) and (
            k + 1 >= end or doc[k + 1].pos_ not in ("NOUN", "PROPN", "NUM", "ADJ")
        ):
            break  # "on the smaller one", "in front of the second"
        if w in (",", ";", ":"):
            break  # "a ring 20 cm across, one cube high": no object after a comma
        if tok.pos_ in ("DET", "NUM", "ADJ", "ADV", "PUNCT", "SYM") or w in ("x", "by", "-"):
            k += 1
            continue
        if w in lx.SIZE_WORDS or (w in lx.REGION_WORDS and doc[k].dep_ in ("amod", "compound")):
            k += 1
            continue
        if w in _QUANTITY_NOUNS and k + 1 < end and doc[k + 1].lower_ == "of":
            k += 2  # "a pair of stacks", "a couple of towers"
            continue
        if (
            tok.dep_ == "compound"
            and k + 1 < end
            and doc[k + 1].pos_ in ("NOUN", "PROPN")
            and w not in lx.REGION_WORDS
        ):
            k += 1
            continue
        break
    if k >= end:
        return None, False
    w = doc[k].lower_
    if w in lx.REGION_WORDS or w in ("corner", "corners", "table", "edge", "side", "robot"):
        return k, False
    if w in ("each", "top") or (w == "other" and k > 0 and doc[k - 1].lower_ == "each"):
        return k, False  # "on top of each other"
    if empty:
        return k, False
    if w in _PRONOUNS and doc[k].pos_ in ("PRON", "DET", "NUM", "NOUN"):
        return k, True
    if w in _ORDINALS:
        return k, True
    if w in _BASES:
        return k, strong
    return k, _is_structure_noun(doc, k)


_COMPONENTS = {
    "castle": {"enclosure", "wall", "tower", "row"},
    "canopy": {"tower", "canopy", "grid"},
    "bridge": {"tower"},
    "arch": {"tower"},
    "enclosure": {"wall"},
}


def _component(doc: Doc, clause: list[int], marker: int, head: int) -> bool:
    """The object noun names a part of the structure before the marker ("on pillars")."""
    before = [lx.SHAPE_WORDS[doc[i].lower_] for i in clause if i < marker and
              doc[i].lower_ in lx.SHAPE_WORDS]  # fmt: skip
    family = lx.SHAPE_WORDS.get(doc[head].lower_)
    if not before or family is None:
        return False
    return family in _COMPONENTS.get(before[-1], set()) and doc[head].lower_.endswith("s")


def _structure(doc: Doc) -> tuple[list[_Phrase], list[_Rel]]:
    phrases: list[_Phrase] = []
    rels: list[_Rel] = []
    stacking = False
    for ci, (clause, sequenced) in enumerate(_clauses(doc)):
        first_phrase, first_rel = len(phrases), len(rels)
        _clause_phrases(doc, clause, ci, phrases, rels)
        new = rels[first_rel:]
        if not new and stacking and sequenced and len(phrases) == first_phrase + 1:
            # "… a 4x1 row on it. Then 3x1. Then 2x1.": a step in a stack goes on top
            rels.append(_Rel("on", first_phrase, None))
            continue
        stacking = any(r.kind == "on" for r in new)
    for p in phrases:
        p.text = "".join(doc[k].text_with_ws for k in p.tokens).strip()
    return phrases, rels


def _clause_phrases(
    doc: Doc, clause: list[int], ci: int, phrases: list[_Phrase], rels: list[_Rel]
) -> None:
    end = clause[-1] + 1
    lower = [t.lower_ for t in doc]
    markers: list[tuple[int, int, str, str | None]] = []  # (start, end, kind, side)
    k = clause[0]
    # verbs: "surround X with Y", "join X and Y with Z", "top it with a beam"
    verb: tuple[int, str] | None = None
    for i in clause:
        lemma = doc[i].lemma_.lower()
        if doc[i].tag_ in ("VB", "VBP") or (i == clause[0] and doc[i].tag_ != "VBN"):
            if lemma in _VERB_AROUND or lower[i] in _VERB_AROUND:
                verb = (i, "v_around")
            elif lemma in _VERB_JOIN or lower[i] in _VERB_JOIN:
                verb = (i, "v_join")
            elif lemma in _VERB_TOP and lower[i] in _VERB_TOP:
                verb = (i, "v_top")
            if verb:
                break
    if verb is not None:
        v, kind = verb
        prep = next(
            (i for i in clause if i > v and lower[i] in ("with", "by", "using", "in")), None
        )
        if prep is not None and _object_head(doc, prep + 1, end)[1]:
            markers.append((v, v + 1, kind + "_verb", None))
            markers.append((prep, prep + 1, kind, None))
    while k < end:
        if markers and any(s <= k < e for s, e, _, _ in markers):
            k += 1
            continue
        found = None
        for words_, kind, side in _MARKERS:
            n = len(words_)
            if tuple(lower[k : k + n]) == words_ and k + n <= end:
                found = (words_, kind, side)
                break
        if found is None:
            k += 1
            continue
        words_, kind, side = found
        n = len(words_)
        strong = words_ in (("on", "top", "of"), ("on", "the", "top", "of"), ("atop",))
        head, is_structure = _object_head(doc, k + n, end, strong)
        if is_structure and head is not None and kind == "on" and _component(doc, clause, k, head):
            k += n
            continue  # "a bridge on pillars 3 high": the bridge's own pillars
        numeric_before = k > clause[0] and (
            doc[k - 1].like_num
            or (lower[k - 1] in lx.PART_WORDS and k - 2 >= 0 and doc[k - 2].like_num)
        )
        implicit = (
            (kind == "on" and words_[-1] == "top" and (head is None or not is_structure))
            or (kind == "inside" and head is None)
            or kind == "next_implicit"
        )
        if kind == "next" and head is None and words_[0] in ("alongside", "beside", "besides"):
            kind, implicit = "next_implicit", True  # "… then a second row alongside"
        if numeric_before and kind == "on" and words_[0] in ("above", "over"):
            k += n
            continue
        if kind == "inside_ref":
            if head is None or doc[head].lower_ not in ("it", "them"):
                k += n
                continue
            kind = "inside"
        overlaps = any(a < k + n and k < b for a, b, _, _ in markers)
        if (is_structure or implicit) and not overlaps:
            markers.append((k, k + n, kind, side))
        k += n
    if not markers:
        phrases.append(_Phrase(tokens=list(clause), clause=ci))
        return
    markers.sort()
    # cut the clause into segments between markers
    segments: list[list[int]] = []
    cur: list[int] = []
    bounds = iter(markers)
    m = next(bounds, None)
    for i in clause:
        while m is not None and i >= m[1]:
            m = next(bounds, None)
        if m is not None and m[0] <= i < m[1]:
            if i == m[0]:
                segments.append(cur)
                cur = []
            continue
        cur.append(i)
    segments.append(cur)
    lead = [i for i in segments[0] if doc[i].lower_ not in words.HARMLESS and not doc[i].is_space]
    if markers and not lead:
        # "On top of two 2-cube towers, a beam.": the subject follows the object, after the
        # first comma of the last segment (or the verb: "To the right of a tower goes a row")
        last = segments[-1]
        commas = [n for n, i in enumerate(last) if doc[i].lower_ == ","]
        verbs = [n for n, i in enumerate(last) if doc[i].lower_ in _FRONTED_VERBS and n]
        cut = commas[0] if commas else (verbs[0] if verbs and len(markers) == 1 else None)
        if cut is None and last and doc[last[0]].lower_ in ("it", "them", "that", "this"):
            cut = 0  # "on it a tower of 3": the pronoun is the object
        if cut is None:
            # "behind the wall 3 long and 2 high a 3-cube tower": a second noun phrase
            articles = [
                n
                for n, i in enumerate(last)
                if n > 0
                and doc[i].lower_ in ("a", "an")
                and _names_structure(doc, last[n : n + 5])
                and _names_structure(doc, last[:n])
            ]
            cut = articles[0] - 1 if articles else None
            if cut is not None:
                segments[0] = last[cut + 1 :]
                segments[-1] = last[: cut + 1]
                cut = None
        if cut is not None and _names_structure(doc, last[cut + 1 :]):
            segments[0] = last[cut + 1 :]
            segments[-1] = last[:cut]
    for j in range(len(markers)):
        tail = segments[j + 1]
        commas = [n for n, i in enumerate(tail) if doc[i].lower_ == ","]
        if (
            commas
            and commas[0] <= 2
            and doc[tail[0]].lower_ in ("it", "them", "this", "that")
            and _names_structure(doc, tail[commas[0] + 1 :])
            and not markers[j][2].endswith("_verb")
        ):
            # "a T shape and, left of it, an L shape": the subject follows the pronoun; what
            # stood before the marker is a phrase of its own
            if _names_structure(doc, segments[j]):
                phrases.append(_Phrase(tokens=segments[j], clause=ci))
            segments[j] = tail[commas[0] + 1 :]
            segments[j + 1] = tail[: commas[0]]
    base = len(phrases)
    for seg in segments:
        phrases.append(_Phrase(tokens=seg, clause=ci))
    # relate the segments: marker j sits between segment j and j + 1
    for j, (_, _, kind, side) in enumerate(markers):
        before, after = base + j, base + j + 1
        if kind.endswith("_verb"):
            continue
        if kind == "inside" and any(doc[i].lower_ in _SPACES_WORDS for i in phrases[before].tokens):
            continue  # "an enclosure with a 2 by 2 space inside it": its own inside
        after_toks = phrases[after].tokens
        named = bool(after_toks) and _object_head(doc, after_toks[0], after_toks[-1] + 1)[1]
        pronoun = bool(after_toks) and all(
            doc[i].lower_ in ("it", "them", "its", "top", "of", "the", "middle", "centre", "and")
            or doc[i].is_punct
            for i in after_toks
        )
        if (
            kind in ("on", "inside", "next")
            and (not named or pronoun)
            and (kind != "next" or pronoun)
        ):
            # "a block with a single cube on top", "an enclosure with a pyramid inside":
            # the structure after "with" is the subject, the one before it the object
            toks = phrases[before].tokens
            withs = [n for n, i in enumerate(toks) if doc[i].lower_ == "with"]
            if withs and _names_structure(doc, toks[withs[-1] + 1 :]):
                cut = withs[-1]
                phrases[before].tokens = toks[:cut]
                phrases[after].tokens = toks[cut + 1 :] + phrases[after].tokens
                if pronoun:
                    phrases[after].tokens = toks[cut + 1 :]  # the pronoun names the first
                if kind == "on":
                    rels.append(_Rel("on", after, before))
                elif kind == "next":
                    rels.append(_Rel("next", after, before, side))
                else:
                    rels.append(_Rel("around", before, after))
                continue
            if kind == "inside" and not named:
                continue  # "with a 2 by 2 space inside": the ring's own inside
        if kind == "v_around":
            rels.append(_Rel("around", after, before))
        elif kind == "v_join":
            rels.append(_Rel("joined", before, after))
        elif kind == "v_top":
            rels.append(_Rel("on", after, before))
        elif kind == "on":
            implicit = (
                not phrases[after].tokens
                or not _object_head(doc, phrases[after].tokens[0], phrases[after].tokens[-1] + 1)[1]
            )
            rels.append(_Rel("on", before, None if implicit else after))
        elif kind == "under":
            rels.append(_Rel("on", after, before))
        elif kind == "around":
            rels.append(_Rel("around", before, after))
        elif kind == "inside":
            rels.append(_Rel("around", after, before))
        elif kind == "next":
            rels.append(_Rel("next", before, after, side))
        elif kind == "next_implicit":
            rels.append(_Rel("next", before, None, side))  # "to its right": the one before
        elif kind == "joined":
            rels.append(_Rel("joined", before, after))
        elif kind == "join":
            rels.append(_Rel("joined", after, before))
        elif kind == "topped":
            rels.append(_Rel("on", after, before))


# -- 5. slot filling ------------------------------------------------------------------------
def _fill(phrases: list[_Phrase], rels: list[_Rel], st: _State, doc: Doc) -> list[StructureSpec]:
    structures: list[StructureSpec] = []
    pending: list[str] = []
    joiners = {r.object for r in rels if r.kind == "joined"} | {
        r.subject for r in rels if r.kind == "on" and _beam_only(phrases[r.subject].text)
    }
    for k, p in enumerate(phrases):
        content = [
            w
            for w in re.findall(r"[a-z0-9.]+", p.text.lower())
            if w not in words.HARMLESS or w in lx.SHAPE_WORDS
        ]
        earlier = [
            i
            for q in phrases[:k]
            if q.clause < p.clause and q.count
            for i in range(q.first, q.first + q.count)
        ]
        pick = _pick(p.text, structures, earlier)
        if pick is not None and structures:
            p.structure = pick
            p.ref = next(
                (
                    j
                    for j, q in enumerate(phrases[:k])
                    if q.count and q.first <= pick < q.first + q.count
                ),
                None,
            )
            if p.ref is not None:
                continue
            p.structure = None
        ref = _reference(p, phrases[:k])
        if ref is not None:
            p.ref = ref
            continue
        if not content:
            continue
        if k in joiners and all(w in _BEAMS or w in lx.PART_WORDS or w == "top" for w in content):
            continue  # "a beam", "a bridge on top" as what joins the towers: no own structure
        if _modify(p, phrases[:k], structures, st):
            continue
        if _COUNT_ONLY.match(p.text) and [q for q in phrases[:k] if q.spec is not None]:
            grown = _continues(p, phrases[:k], st.cell)  # "make a tower? 4 cubes?"
            if grown is not None:
                before_count, prev = grown
                assert prev.spec is not None
                structures[prev.first : prev.first + before_count] = list(prev.spec.structures)
                continue
        if _REMOVAL.match(p.text) and [q for q in phrases[:k] if q.spec is not None]:
            # "then pull out the middle cube", "push them together": a change SDI cannot
            # make to a structure it built; never a new structure read from those words
            st.material.append(p.text)
            st.notes.append(
                f"ignored '{p.text}': SDI builds structures whole and cannot take parts out, "
                "move or merge them afterwards; describe the result instead"
            )
            continue
        change = next((m for pattern, _ in _MODIFY if (m := pattern.search(p.text))), None)
        tail: _Phrase | None = None
        if change is not None and change.start() > 0:
            # "begin with a 2-step staircase and keep adding steps until it has 4"
            tail = _Phrase(tokens=[], clause=p.clause, text=p.text[change.start() :])
            p.text = re.sub(r"(?:,|\band\b|\bthen\b|\s)+$", "", p.text[: change.start()])
        if pending and not [q for q in phrases[:k] if q.spec is not None]:
            p.text = " , ".join([*pending, p.text])  # "High: 3. Long: 5. Wall."
            pending.clear()
        try:
            spec, unused = _parse_or_base(p, st)
            spec = _copies(spec, p.text, st, structures)
        except SpecError:
            grown = _continues(p, phrases[:k], st.cell)
            if grown is not None:
                before_count, prev = grown
                assert prev.spec is not None
                structures[prev.first : prev.first + before_count] = list(prev.spec.structures)
                continue
            if not [q for q in phrases[:k] if q.spec is not None] and not _chatter(p.text):
                pending.append(p.text)
                continue
            if _chatter(p.text):
                st.ignored.append(p.text)
                st.notes.append(f"ignored '{p.text}': no structure, size or place in it")
                continue
            st.material.append(p.text)
            st.notes.append(f"ignored '{p.text}': no structure named there")
            continue
        same = _same_as_before(p, spec, phrases[:k])
        if same is not None:
            st.notes.append(f"'{p.text}' names the {same} described before")
            continue
        named = _definite(p, spec, phrases[:k], structures)
        if named is not None:
            # "…; the staircase has 3 steps": more about the staircase named before
            said = spec.structures[0].model_dump(exclude_defaults=True, exclude={"shape"})
            structures[named] = structures[named].model_copy(update=said)
            st.notes.append(f"'{p.text}': more about the {spec.structures[0].shape} named before")
            p.count = 0
            continue
        p.spec = spec
        p.first = len(structures)
        p.count = len(spec.structures)
        structures.extend(spec.structures)
        if tail is not None:
            _modify(tail, [p], structures, st)
        st.notes.extend(spec.notes)
        st.material.extend(n for n in spec.notes if n.startswith("ignored"))
        free = list(p.tokens)
        for w in unused:
            tok = next((doc[i] for i in free if doc[i].lower_.replace("'", "") == w), None)
            if tok is not None:
                free.remove(tok.i)
            _account(w, tok, st)
    for text in pending:
        st.material.append(text)
        st.notes.append(f"ignored '{text}': no structure named there")
    return structures


_ONE_CUBE = re.compile(
    r"^(?:\w+\s+)?(?:a|an|one|single|a\s+single|another|1)\s+(?:more\s+)?(?:cube|block|brick|part)"
    r"(?:\s+\w+)?$",
    re.IGNORECASE,
)


def _definite(
    p: _Phrase, spec: Spec, before: list[_Phrase], structures: list[StructureSpec]
) -> int | None:
    """ "the staircase has 3 steps" after a staircase was named: the index of that one."""
    m = re.match(r"^\W*(?:the|that|this)\s+(\w+)(?:\s+(\w+))?", p.text, re.IGNORECASE)
    if not m or len(spec.structures) != 1:
        return None
    family = lx.SHAPE_WORDS.get(m.group(1).lower()) or lx.SHAPE_WORDS.get(
        (m.group(2) or "").lower()
    )
    if family is None or family != spec.structures[0].shape:
        return None
    matches = [
        i for q in before if q.count and q.spec is not None
        for i in range(q.first, q.first + q.count) if structures[i].shape == family
    ]  # fmt: skip
    if len(matches) != 1:
        return None
    said = spec.structures[0].model_dump(exclude_defaults=True, exclude={"shape"})
    known = structures[matches[0]].model_dump(exclude_defaults=True, exclude={"shape"})
    words_ = set(re.findall(r"[a-z]+", p.text.lower()))
    if any(known.get(k) not in (None, v) for k, v in said.items()) or words_ & (
        set(lx.REGION_WORDS) | _COPY | {"other", "first", "second", "third", "last"}
    ):
        return None  # "then the right tower of 2": another tower
    return matches[0]


def _same_as_before(p: _Phrase, spec: Spec, before: list[_Phrase]) -> str | None:
    """ "Steps: 5. Shape: staircase.": a bare family name in a later clause names the one
    structure described before, not a second one."""
    if len(spec.structures) != 1 or spec.structures[0].model_dump(
        include=set(_SIZES) - {"part"}, exclude_defaults=True
    ):
        return None
    said = set(re.findall(r"[a-z]+", p.text.lower()))
    if said & (_COPY | {"and", "also", "more", "two", "three", "other", "plus", "then"}):
        return None
    built = [q for q in before if q.spec is not None and q.count]
    if not built or built[-1].clause == p.clause or built[-1].count != 1:
        return None
    prev = built[-1].spec
    assert prev is not None
    shape = spec.structures[0].shape
    described = prev.structures[-1].model_dump(
        include=set(_SIZES) - {"part"}, exclude_defaults=True
    )
    return shape if prev.structures[-1].shape == shape and described else None


def _parse_or_base(p: _Phrase, st: _State) -> tuple[Spec, list[str]]:
    """The phrase grammar's reading; "a sturdy base" with nothing else named is a platform,
    "a cube" on its own one part."""
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


def _beam_only(text: str) -> bool:
    said = [w for w in re.findall(r"[a-z]+", text.lower()) if w not in words.HARMLESS]
    return (
        bool(said)
        and all(w in _BEAMS or w in lx.PART_WORDS for w in said)
        and any(w in _BEAMS for w in said)
    )


def _reference(p: _Phrase, before: list[_Phrase]) -> int | None:
    """A phrase that only points at an earlier one ("it", "them", "the base")."""
    said = p.text.lower().replace(",", " ").split()
    led = False
    while said and said[0] in _LEAD_VERBS:
        said, led = said[1:], True  # "put the cube": the cube named before
    rest = " ".join(said)
    words_ = [w for w in said if w not in ("the", "of")]
    if not words_ or len(words_) > 6:
        return None
    built = [j for j, q in enumerate(before) if q.spec is not None or q.ref is not None]
    if not built:
        return None
    sides = [w for w in words_[1:] if w in ("left", "right", "front", "back")]
    trailing = all(
        w in lx.REGION_WORDS or w in ("on", "to", "at", "in", "its", "side", "hand", "of")
        for w in words_[1:]
    )
    if words_[0] in _PRONOUNS and (len(words_) <= 2 or trailing) and len(words_) <= 6 and not led:
        p.side = sides[0] if sides else None
        if words_[0] in ("them", "these", "those"):
            many = [j for j in built if before[j].count > 1]
            return _target(before, many[-1] if many else built[-1])
        return _target(before, built[-1])
    if (
        len(words_) <= 2
        and words_[-1] in _GENERIC | _BASES | set(lx.SHAPE_WORDS) | {"cube", "block", "brick"}
        and rest.startswith(("the", "its"))
    ):
        noun = words_[-1]
        if noun in ("base", "foundation", "bottom", "first", "platform", "plinth"):
            return _target(before, built[0])
        if noun in ("cube", "block", "brick", "part"):
            # "the cube": the structure of one part named before
            for j in reversed(built):
                spec = before[_target(before, j)].spec
                if spec is not None and any(
                    (s.shape == "tower" and s.height == 1) or (s.shape == "row" and s.length == 1)
                    for s in spec.structures
                ):
                    return _target(before, j)
            return None
        family = lx.SHAPE_WORDS.get(noun)
        for j in reversed(built):
            spec = before[_target(before, j)].spec
            if spec is not None and any(s.shape == family for s in spec.structures):
                return _target(before, j)
        if family is None:
            return _target(before, built[-1])  # "the structure", "the other one"
        return None  # "the tower" named for the first time: a structure of its own
    return None


_PICK = re.compile(
    r"^(?:\w+\s+)?the\s+(first|second|third|fourth|last|smaller|smallest|larger|largest|bigger|"
    r"biggest|taller|tallest|shorter|shortest|lower|higher)(?:\s+(?:one|"
    + "|".join(sorted(w for w in lx.SHAPE_WORDS if w.isalpha()))
    + r"))?$",
    re.IGNORECASE,
)


def _pick(text: str, structures: list[StructureSpec], among: list[int]) -> int | None:
    """ "the first one", "the smaller one", "the taller tower": one of the structures named
    in earlier clauses (`among`; all so far when empty)."""
    m = _PICK.match(text.strip())
    if not m or not structures:
        return None
    among = among or list(range(len(structures)))
    word = m.group(1).lower()
    order = {"first": 0, "second": 1, "third": 2, "fourth": 3}
    if word in order:
        return among[order[word]] if order[word] < len(among) else None
    if word == "last":
        return among[-1]

    def size(s: StructureSpec) -> float:
        tall = s.height or s.steps or (s.height_m or 0) / 0.05 or 1
        wide = (s.length or 1) * (s.width or 1)
        return float(tall if word in ("taller", "tallest", "shorter", "shortest", "lower",
                                      "higher") else tall * wide)  # fmt: skip

    sizes = [size(structures[i]) for i in among]
    big = word in ("larger", "largest", "bigger", "biggest", "taller", "tallest", "higher")
    target = max(sizes) if big else min(sizes)
    if sizes.count(target) != 1:
        return None
    return among[sizes.index(target)]


def _target(phrases: list[_Phrase], j: int) -> int:
    while phrases[j].ref is not None:
        j = phrases[j].ref  # type: ignore[assignment]
    return j


def _continues(p: _Phrase, before: list[_Phrase], cell: CellConfig) -> tuple[int, _Phrase] | None:
    """A phrase with no structure that modifies the one before ("Make it 5 cubes tall"):
    the earlier phrase read again with it, and how many structures it had."""
    built = [q for q in before if q.spec is not None]
    if not built or p.ref is not None:
        return None
    prev = built[-1]
    try:
        spec, _ = parse_phrase(prev.text + " , " + p.text, cell)
    except SpecError:
        return None
    if prev.spec is not None and spec.structures == prev.spec.structures:
        return None
    count = prev.count
    if len(spec.structures) != count:
        return None  # the later words named a structure after all: not a continuation
    prev.text = prev.text + " , " + p.text
    prev.spec = spec
    p.count = 0
    return count, prev


# Words that make a clause more than chatter (ambiguous shape nouns like "well" do not).
_USABLE = (
    set(lx.SHAPE_WORDS) | set(lx.SIZE_WORDS) | set(lx.DIMENSION_WORDS) | set(lx.REGION_WORDS)
    | lx.LEVEL_WORDS | lx.STEP_WORDS | lx.PART_WORDS | set(lx.UNITS_M) | _BEAMS
) - lx.AMBIGUOUS_SHAPES - {"well", "item", "items", "object", "objects", "unit"}  # fmt: skip


def _chatter(text: str) -> bool:
    """A clause with nothing the Specifier could use ("The visitors arrive at 10")."""
    said = re.findall(r"[a-z]+|\d+", text.lower())
    if any(w.isdigit() for w in said) and not any(w in lx.PART_WORDS for w in said):
        return bool(
            re.search(r"\b(?:item|order|ticket|job|room|at|by|until|before|after)\b", text, re.I)
        )
    return not any(w in _USABLE for w in said)


def _attached(tok: Token) -> bool:
    """`tok` modifies a structure (or a part) in the parse, not the chatter around it."""
    seen = 0
    t = tok
    while seen < 8:
        if t.lower_ in lx.SHAPE_WORDS or t.lower_ in lx.PART_WORDS:
            return t.i != tok.i or tok.pos_ != "NOUN"
        if t.lower_ in ("for",) and t.dep_ == "prep":
            return False  # "for the demo", "for a teddy bear": a purpose
        if t.head.i == t.i:
            return False
        if t.dep_ in ("advcl", "intj", "parataxis", "discourse", "ccomp", "mark"):
            return False
        if t.dep_ == "relcl" and any(
            c.lower_ in ("could", "can", "would", "might") for c in t.children
        ):
            return False  # "a gateway a cube could pass under"
        t = t.head
        seen += 1
    return False


def _account(word: str, tok: Token | None, st: _State) -> None:
    if word in (",", ":", ";", "(", ")", "=", "+", "&", "*"):
        return
    pos = tok.pos_ if tok is not None else None
    numeric = word[:1].isdigit()
    if tok is None and not numeric and word not in words.CORRECTABLE | words.NEGATIONS:
        return  # a piece of a contraction ("we've" → "weve") or a symbol
    known = (
        word in words.CORRECTABLE or word in words.NEGATIONS or numeric
    ) and word not in words.HARMLESS
    if tok is not None and not known and not _attached(tok):
        if word not in words.HARMLESS and word not in words.CONSULTED:
            st.ignored.append(word)
            st.notes.append(f"ignored '{word}': not about the structure")
        return
    if tok is not None and word in words.NEGATIONS and not _attached(tok):
        st.ignored.append(word)
        return
    if words.is_material(word, pos):
        st.material.append(word)
        st.ignored.append(word)
        st.notes.append(f"ignored '{word}': not used by the reading")
    elif word not in words.HARMLESS and word not in words.CONSULTED and word not in lx.FILLER:
        st.ignored.append(word)


# -- 6. composition -------------------------------------------------------------------------
def _relate(
    phrases: list[_Phrase], rels: list[_Rel], structures: list[StructureSpec], st: _State
) -> tuple[list[Relation], list[StructureSpec]]:
    relations: list[Relation] = []
    drop: set[int] = set()
    replace: dict[int, StructureSpec] = {}

    def built(j: int | None, fallback: int) -> int | None:
        if j is None:
            # "on top" with no object: the phrase before the subject
            cands = [q for q in range(fallback) if phrases[q].count and phrases[q].spec]
            return cands[-1] if cands else None
        j = _target(phrases, j)
        return j if phrases[j].count and phrases[j].spec is not None else None

    joiners = {r.object for r in rels if r.kind == "joined"}
    for r in rels:
        subj = r.subject
        if phrases[subj].modified or (r.object is not None and phrases[r.object].modified):
            continue  # "add a third layer on it": already a change of that structure
        if r.kind == "on" and subj in joiners:
            continue  # "joined by a bridge on top": the joining beam lies on top anyway
        obj = built(r.object, r.subject)
        if r.kind == "joined":
            pillars = built(r.subject, r.subject)
            pillars = (
                _target(phrases, r.subject) if phrases[r.subject].ref is not None else (pillars)
            )
            between = _between(phrases, pillars, r.object, structures)
            if between:
                relations.extend(between)
                st.notes.append("placed between the two, side by side")
                continue
            _join(phrases, pillars, r.object, structures, replace, drop, st)
            continue
        s_ref = phrases[subj].ref is not None
        subj = _target(phrases, subj)
        if not phrases[subj].count or phrases[subj].spec is None:
            if phrases[subj].tokens and r.kind == "on" and obj is not None:
                # "a beam on top of the two towers": the beam joins them
                _join(phrases, obj, subj, structures, replace, drop, st)
                continue
            st.material.append(f"relation {r.kind}")
            st.notes.append(f"ignored a relation '{r.kind}': its subject is not a structure")
            continue
        s_first, s_last = phrases[subj].first, phrases[subj].first + phrases[subj].count - 1
        o_ref = r.object is not None and phrases[r.object].ref is not None
        if r.object is None:
            # "X with Y on top", "on top" alone: the structure before the subject
            s_idx = s_last
            o_idx = (
                s_last - 1
                if phrases[subj].count > 1
                else (phrases[obj].first + phrases[obj].count - 1 if obj is not None else -1)
            )
        elif obj is None:
            o_idx = -1
            s_idx = s_last
        elif obj == subj:
            # "a staircase with a tower next to it", "a ring with a tower inside it": the
            # pronoun's side takes the first structure of the phrase, the other the last
            s_idx = s_first if s_ref else s_last
            o_idx = s_first if o_ref or not s_ref else s_last
            if phrases[subj].count == 1:
                o_idx = s_first - 1
        else:
            s_idx = s_last
            o_idx = phrases[obj].first + phrases[obj].count - 1
        if phrases[r.subject].structure is not None:
            s_idx = phrases[r.subject].structure  # type: ignore[assignment]
        if r.object is not None and phrases[r.object].structure is not None:
            o_idx = phrases[r.object].structure  # type: ignore[assignment]
        if o_idx < 0 or o_idx == s_idx:
            st.material.append(f"relation {r.kind}")
            st.notes.append(f"ignored '{r.kind}': no structure to relate '{phrases[subj].text}' to")
            continue
        if obj is None:
            obj = subj
        picked = r.object is not None and phrases[r.object].structure is not None
        if r.kind == "on" and phrases[obj].count > 1 and phrases[subj].count == 1 and not picked:
            _join(phrases, obj, subj, structures, replace, drop, st)
            continue
        subject = replace.get(s_idx, structures[s_idx])
        obj_spec = replace.get(o_idx, structures[o_idx])
        subject = _copy_if_asked(phrases[subj], subject, obj_spec, st)
        if r.kind == "around" and obj_spec.shape in ("enclosure", "castle"):
            subject, obj_spec = obj_spec, subject
            s_idx, o_idx = o_idx, s_idx
        if r.kind == "around" and subject.shape not in ("enclosure", "castle"):
            st.notes.append(f"a {subject.shape} around another structure: built as a ring")
            subject = StructureSpec(shape="enclosure", height=subject.height, part=subject.part)
        replace[s_idx] = subject
        if any(rel.subject == s_idx for rel in relations):
            st.material.append(f"relation {r.kind}")
            st.notes.append(f"ignored a second relation of '{phrases[subj].text}'")
            continue
        kind: RelationKind = _KINDS[r.kind]
        placed = {"at_x": subject.at_x, "at_y": subject.at_y, "region": subject.region}
        if kind != "around" and any(v is not None for v in placed.values()):
            # the unit stands where the object stands: a position said of the subject moves
            # to the object when the object has none
            if obj_spec.at_x is None and obj_spec.at_y is None and obj_spec.region is None:
                replace[o_idx] = obj_spec.model_copy(update=placed)
            else:
                st.notes.append(
                    f"the position of the {subject.shape} follows the {obj_spec.shape} it is "
                    f"{kind.replace('_', ' ')}"
                )
            replace[s_idx] = subject.model_copy(update=dict.fromkeys(placed))
        side = r.side or (phrases[r.object].side if r.object is not None else None)
        relations.append(Relation(kind=kind, subject=s_idx, object=o_idx, side=side))
    for k, s in replace.items():
        structures[k] = s
    if drop:
        keep = [k for k in range(len(structures)) if k not in drop]
        index = {old: new for new, old in enumerate(keep)}
        relations = [
            r.model_copy(update={"subject": index[r.subject], "object": index[r.object]})
            for r in relations
            if r.subject in index and r.object in index
        ]
        structures = [structures[k] for k in keep]
    return relations, structures


def _copy_if_asked(
    p: _Phrase, subject: StructureSpec, other: StructureSpec, st: _State
) -> StructureSpec:
    """ "a second row", "another one like it": the same parameters as the structure referred to."""
    said = set(p.text.lower().split())
    explicit = subject.model_dump(exclude_defaults=True, exclude={"shape"})
    if said & _COPY and not explicit and subject.shape == other.shape:
        st.notes.append(f"'{p.text}': the same {other.shape} as the one it stands on or beside")
        return other.model_copy(update={"at_x": None, "at_y": None, "region": None})
    return subject


def _between(
    phrases: list[_Phrase], pillars: int | None, middle: int | None, structures: list[StructureSpec]
) -> list[Relation]:
    """ "a 2x2 block between a wall and a tower": the three in a row, the middle one between
    (empty when the middle one is a beam or bridge that joins them instead)."""
    if pillars is None or middle is None or phrases[pillars].count != 2:
        return []
    m = phrases[middle]
    target = _target(phrases, middle)
    spec = phrases[target].spec
    if spec is None or _beam_only(m.text):
        return []
    if m.structure is not None:
        x = m.structure
    else:
        x = phrases[target].first + phrases[target].count - 1
    if structures[x].shape in ("bridge", "arch"):
        return []
    a, b = phrases[pillars].first, phrases[pillars].first + 1
    if x in (a, b):
        return []
    return [
        Relation(kind="next_to", subject=x, object=a, side="back"),
        Relation(kind="next_to", subject=b, object=x, side="back"),
    ]


def _join(
    phrases: list[_Phrase],
    pillars: int | None,
    joiner: int | None,
    structures: list[StructureSpec],
    replace: dict[int, StructureSpec],
    drop: set[int],
    st: _State,
) -> None:
    """Towers "joined by" a beam or bridge: a bridge standing on them as its pillars."""
    if pillars is None or not phrases[pillars].count:
        st.material.append("relation joined")
        st.notes.append("ignored 'joined by': no towers to join")
        return
    p = phrases[pillars]
    idx = list(range(p.first, p.first + p.count))
    towers = [replace.get(k, structures[k]) for k in idx]
    if len(towers) == 1 and towers[0].shape in ("bridge", "arch", "canopy"):
        return  # "a bridge: two pillars … with a beam across the top": the bridge's own beam
    if len(towers) == 1 and towers[0].shape == "row" and (towers[0].length or 0) >= 2:
        # "a beam spanning a pair of single cubes": each cube is a pillar one part high
        n = towers[0].length or 2
        towers = [towers[0].model_copy(update={"shape": "tower", "height": 1, "length": None,
                                               "gap_m": None})] * n  # fmt: skip
    if len(towers) < 2 or any(t.shape != "tower" for t in towers):
        shapes = ", ".join(t.shape for t in towers)
        st.material.append("relation joined")
        st.notes.append(
            f"ignored 'joined by': only two or more towers can carry a beam (got {shapes})"
        )
        return
    heights = {t.height or (3 if t.height_m is None else None) for t in towers}
    metres = {t.height_m for t in towers if t.height_m is not None}
    if len(heights) > 1 or len(metres) > 1:
        st.material.append("relation joined")
        st.notes.append("ignored 'joined by': towers of different heights cannot carry one beam")
        return
    first = towers[0]
    bridge = StructureSpec(
        shape="bridge",
        height=first.height,
        height_m=first.height_m,
        spans=len(towers) - 1,
        at_x=first.at_x,
        at_y=first.at_y,
        region=first.region,
        axis=first.axis,
    )
    if joiner is not None and phrases[joiner].spec is not None:
        j = phrases[joiner]
        own = [x.shape for x in j.spec.structures] if j.spec else []
        if any(shape not in ("bridge", "arch") for shape in own):
            st.material.append("relation between")
            st.notes.append(
                f"ignored 'between': only a beam or bridge can join towers, not a "
                f"{own[0]}; built them side by side"
            )
            return
        extra = j.spec.structures[0] if j.spec else None
        if extra is not None and extra.shape == "bridge" and extra.span is not None:
            bridge = bridge.model_copy(update={"span": extra.span})
        drop.update(range(j.first, j.first + j.count))
    st.notes.append(
        f"{len(towers)} towers joined by a beam: a bridge with {len(towers) - 1} span(s) on them"
    )
    replace[idx[0]] = bridge
    drop.update(idx[1:])


def _unstack(s: StructureSpec, st: _State) -> StructureSpec:
    if s.shape == "tower":
        return StructureSpec(
            shape="row", length=s.height or 3, at_x=s.at_x, at_y=s.at_y, region=s.region
        )
    return s


_GENERIC_NOUNS = re.compile(
    r"\b(something|structure|thing|shape|object|construction|sculpture|build|piece|model)\b",
    re.IGNORECASE,
)


def _open(text: str) -> tuple[str, list[str]]:
    """An open description with no family named: the family its size words suggest."""
    m = _GENERIC_NOUNS.search(text)
    said = set(re.findall(r"[a-z]+", text.lower()))
    if not m or not said & set(lx.SIZE_WORDS):
        return text, []  # "build something": nothing to go on
    if said & {"wide", "flat", "low", "broad", "long", "spread"}:
        family = "platform" if not said & {"long"} else "row"
    else:
        family = "tower"
    note = f"no structure named: read '{m.group(0)}' as a {family}"
    return text[: m.start()] + family + text[m.end() :], [note]


# -- errors ---------------------------------------------------------------------------------
def _understood(doc: Doc) -> dict[str, object]:
    out: dict[str, object] = {}
    shapes = [lx.SHAPE_WORDS[t.lower_] for t in doc if t.lower_ in lx.SHAPE_WORDS]
    if shapes:
        out["structures"] = shapes
    nums = [t.text for t in doc if t.like_num]
    if nums:
        out["numbers"] = nums
    parts = [t.lower_ for t in doc if t.lower_ in lx.PART_WORDS]
    if parts:
        out["parts"] = parts
    regions = [lx.REGION_WORDS[t.lower_] for t in doc if t.lower_ in lx.REGION_WORDS]
    if regions:
        out["regions"] = regions
    unknown = [
        t.text for t in doc if t.is_alpha and t.lower_ not in words.VOCABULARY and not t.is_stop
    ]
    if unknown:
        out["unknown_words"] = unknown[:20]
    return out


def _no_structure(st: _State, doc: Doc, command: str) -> None:
    known = ", ".join(sorted(set(lx.SHAPE_WORDS.values())))
    understood = _understood(doc)
    try:
        parse_phrase(doc.text, st.cell)
    except SpecError as exc:
        if exc.understood and "not a usable count" not in str(exc):
            understood = {**understood, **exc.understood}
        elif "not a usable count" in str(exc):
            raise SpecError(str(exc), understood=understood) from None
    raise SpecError(
        "no structure recognised in the command; name one of: "
        + known
        + " (e.g. 'a tower of 4 cubes', 'a 3 by 3 grid on the left')",
        understood=understood,
    )
