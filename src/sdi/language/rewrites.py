"""Stage 2: the rewrite table. Negations, hedges and idioms with one clear reading become the
words the grammar reads ("not too tall" → medium, "not on the left" → on the right, "don't
stack them" → side by side), each with a note when it changes the meaning.

Each entry of `REWRITES` is ``(pattern, replacement, note)``: the replacement is a format
string over the match's groups (``{opposite}`` names the opposite side), or the key of a
computed handler in `sdi.language.handlers`."""

from __future__ import annotations

import itertools
import re

from sdi.language.handlers import COUNTED, HANDLERS
from sdi.language.normalise import SPACES
from sdi.language.nouns import families_said, shape_alternation
from sdi.language.state import ReadState
from sdi.spec import lexicon as lx
from sdi.spec.numbers import NUMBER_WORDS, words_to_numbers

_MIDDLE_ONES = r"tower|stack|column|pillar|pyramid|block|wall|row|staircase"
"""The families "the tower in the middle" may name of a line (`_named_in_middle`)."""

_NOT_TOUCHING = re.compile(
    r",?\s*\b(?:but\s+)?(?:(?:not|no|never|without)\s+touch(?:ing)?(?:\s+each\s+other|"
    r"\s+one\s+another|\s+it|\s+them|\s+the\s+(?:ring|wall|row|tower|base|slab|enclosure))?|"
    r"spaced\s+out|spread\s+out|"
    r"with\s+gaps?\s+between\s+them)\b",
    re.IGNORECASE,
)
_OPPOSITE = {**lx.OPPOSITE_SIDE, "middle": "left", "centre": "left", "center": "left"}


_LEVEL_ORDINAL = re.compile(
    r"\b(?:as|for|on|to form)\s+(?:the|a)\s+(?:second|third|fourth|fifth|next|top|final|last|"
    r"upper|new)\s+(?:level|layer|tier|storey|story|floor|row)\b",
    re.IGNORECASE,
)


# a quality document's condition for rejecting the build: "Nonconformance if …", "Reject if …"
_REJECT_IF = (
    r"\b(?:non-?conformance|reject(?:ed)?|fail(?:ed|ure)?|not\s+acceptable|unacceptable|nok)\s+"
    r"if\s+"
)


# Negations and hedges with one clear reading: (pattern, replacement, note).
_SERIES_LEAD = (
    r"\b(?P<n>\d+|two|three|four|five|six)\s+(?P<kind>towers|stacks|columns|pillars)\s*(?:,?\s*please)?"
    r"\s*[;:,]?\s*(?:start(?:ing)?|begin(?:ning)?)\s+(?:with|at|from)\s+(?P<first>\d+|one|two|three|"
    r"four|five)(?:\s+cubes?)?(?:\s+(?:high|tall))?\s*,?\s*"
)
"""'three towers, starting at 2 …': the series' count, family and first height."""

_ITS_SIDE = (
    r"(?:to|on|at)\s+(?:its|the)\s+(?:left|right|front|back)(?:\s+side)?|in\s+front\s+of\s+it|"
    r"behind\s+it"
)
"""Where a copy stands by the one before: "to its left", "in front of it"."""

_REWRITES: list[tuple[re.Pattern[str], str, str]] = [
    (  # "two towers joined by a row of 3 cubes on top": cubes alone would not hold across a gap
        re.compile(
            r"\b(?:(joined|connected|linked|bridged|topped)\s+by|with)\s+an?\s+(?:\d+[- ]cube\s+)?"
            r"(?:row|line|bar|strip)(?:\s+of\s+(?:\d+|two|three|four|five)?\s*(?:cubes|blocks))?\s+"
            r"(?:on\s+top|across\s+(?:the\s+)?tops?|across\s+them|over\s+(?:the\s+)?tops?)"
            r"(?:\s+(?:joining|connecting|linking|bridging)\s+them)?",
            re.IGNORECASE,
        ),
        "{cube_bar}",
        "",
    ),
    (  # "its centre 10 cm from the front edge", "from the left edge 10 cm": a coordinate
        re.compile(
            r"(?:,\s*)?(?:(?:with\s+)?its\s+(?:centre|center)\s+|centred\s+|(?:placed\s+|set\s+)?)?"
            r"(?:(?:about\s+|around\s+|roughly\s+|some\s+)?(\d+(?:\.\d+)?)\s*(mm|cm|m)\s+(?:in\s+|away\s+|"
            r"back\s+)?from\s+the\s+(front|back|left|right)(?:[\s-]hand)?(?:\s+(?:edge|side)|(?=\s*(?:$|[,.;]|"
            r"\s+(?:and|of\s+the\s+(?:table|workspace|bench|cell))\b)))"
            r"|from\s+the\s+(front|back|left|right)(?:[\s-]hand)?\s+(?:edge|side)\s*,?\s*(\d+(?:\.\d+)?)\s*"
            r"(mm|cm|m))(?:\s+of\s+the\s+(?:table|workspace|bench|cell))?(?:\s+to\s+its\s+(?:centre|center))?",
            re.IGNORECASE,
        ),
        "{from_edge}",
        "",
    ),
    (  # "top left of the drawing", "bottom right": seen from above, the robot at the bottom
        re.compile(
            r"\b(?:the\s+)?(top|upper|bottom|lower)[\s-]+(left|right)(?:[\s-]+hand)?(\s+corner)?\b"
            r"(?!\s+(?:cube|block|part|step|brick|one)s?\b)"
            r"(?!\s+(?:corner\s+)?of\s+(?:the\s+|its\s+|each\s+)?(?:wall|tower|slab|block|pyramid|staircase|grid|"
            r"row|structure|base|platform|it|them)\b)"
            r"(?:\s+(?:of|on|in)\s+the\s+(?:drawing|page|sketch|plan|diagram|picture|table|napkin|"
            r"paper|workspace))?",
            re.IGNORECASE,
        ),
        "{top_left}",
        "",
    ),
    (  # "bridge with pillars 3 high", "arch w/ legs of 4": a structure named first, no article
        # (the parser takes "bridge" for the verb)
        re.compile(
            r"(^|[.;!?:\n]\s*|,\s*(?:and\s+|then\s+)?|\b(?:and|then)\s+)(bridge|arch|gate|tower|wall|pyramid|"
            r"staircase|canopy|ring|castle|slab|platform|column)\s+"
            r"(?=(?:with|w/|on|of|at|in|from|made)\b|(?<!tower\s)\d+\s*(?:x|by)\s*\d)",
            re.IGNORECASE,
        ),
        "{0}a {1} ",
        "",
    ),
    (  # "wall 5 long. tower 3 each end.": a placement said without its preposition
        re.compile(
            r"\b(towers?|columns?|cubes?|stacks?|posts?)\s+"
            r"(\d+|one|two|three|four|five)\s+(?=(?:each|either|both)\s+(?:ends?|corners?)\b)",
            re.IGNORECASE,
        ),
        "{0} of {1} at ",
        "",
    ),
    (  # "That's right, stairs.", "yes that is correct": agreement, not a side
        re.compile(
            r"\b(?:that'?s|that\s+is|thats|yes|yeah|exactly)\s+(?:right|correct)\b(?!\s+of\b)",
            re.IGNORECASE,
        ),
        " ",
        "",
    ),
    (  # "between two single towers of 4": two towers, each a structure of its own
        re.compile(
            r"\b(two|three|four|five|six|[2-9])\s+(?:single|separate|individual)\s+"
            r"(?!(?:cubes|blocks|bricks|parts|pieces)\b)(?=[a-z]+s\b)",
            re.IGNORECASE,
        ),
        "{0} ",
        "",
    ),
    (  # "a table with four legs of 3", "an arch with legs of 2 cubes": legs that high
        re.compile(
            r"\b(legs?|posts?|piers?|supports?)\s+of\s+(\d+|one|two|three|four|five|six|seven|"
            r"eight|nine|ten)(?:\s+(?:cubes?|blocks?|bricks?|storeys?|stories|levels?|floors?|courses?))?\b(?!\s*(?:cm|mm|m|by|x|wide|long)\b)",
            re.IGNORECASE,
        ),
        " {0} {1} high ",
        "",
    ),
    (  # "a single layer of 8 cubes in two rows": one layer, of that
        re.compile(
            r"\b(?:a|one)\s+(?:single\s+|flat\s+)?(?:layer|level|course)\s+(?:made\s+)?of\s+"
            r"(?=(?:\d+|two|three|four|five|six|seven|eight|nine|ten|twelve)\s+(?:rows?|lines?|"
            r"cubes?\s+in\s+(?:\d+|two|three|four)\s+rows?))",
            re.IGNORECASE,
        ),
        " ",
        "",
    ),
    (  # "two rows of four, 1 layer": one part high, not a structure of its own
        re.compile(
            r",\s*(?:in\s+)?(?:just\s+)?(?:one|a\s+single|1|single)\s+(?:layer|level|course)"
            r"(?:\s+(?:only|high|thick|tall|deep))?(?=\s*(?:$|[,.;!]))",
            re.IGNORECASE,
        ),
        "{one_layer}",
        "",
    ),
    (  # "wall 5 long, but leave out the middle cube on the top row": parts SDI cannot leave out
        re.compile(
            r",?\s*\b(?:but\s+|and\s+)?(?:leave\s+out|remove|skip|omit|take\s+out|without)\s+the\s+"
            r"(?:middle|centre|center|end|first|last|corner|top|bottom|outer|two\s+end)\s+"
            r"(?:cubes?|parts?|bricks?|blocks?)\s+(?:on|of|in|from)\s+the\s+(?:top|bottom|middle|"
            r"first|second|last|upper|lower)\s+(?:row|layer|course|level|tier)\b",
            re.IGNORECASE,
        ),
        "{parts_out}",
        "",
    ),
    (  # "on no account to be placed on the left": not on the left
        re.compile(
            r"\bon\s+no\s+account\s+(?:(?:is\s+it\s+|are\s+they\s+)?to\s+(?:be\s+)?)?"
            r"(?:placed|put|built|set|go|stand|be)?\b",
            re.IGNORECASE,
        ),
        " not ",
        "",
    ),
    (  # "Nonconformance if the two towers touch": they must not
        re.compile(
            _REJECT_IF
            + r"(?:the\s+)?(?:two\s+|both\s+|any\s+)?(?:towers?|structures?|stacks?|items?|parts?|"
            r"they|of\s+them)?\s*(?:touch|touches|are\s+touching|is\s+touching)\b(?:\s+each\s+other)?",
            re.IGNORECASE,
        ),
        " not touching ",
        "",
    ),
    (  # "Reject if any part is within 10 cm of the front edge": everything at the other side
        re.compile(
            _REJECT_IF
            + r"(?:any|a)\s+(?:part|cube|piece|structure)\s+(?:is\s+)?(?:within|closer\s+than|"
            r"nearer\s+than)\s+\d+(?:\.\d+)?\s*(?:mm|cm|m)\s+(?:of|to|from)\s+the\s+(left|right|front|back)"
            r"(?:\s+(?:edge|side))?\b",
            re.IGNORECASE,
        ),
        "{keep_off}",
        "",
    ),
    (  # "do not put the pyramid on the left": it, on the other side
        re.compile(
            r"\b(?:do\s+not|never)\s+(put|place|build|set|stand)\s+(the\s+\w+|it|them)\s+"
            r"(?:on|in|at)\s+the\s+(left|right|front|back)(?:\s+(?:side|half|part|end))?\b"
            r"(?!\s+(?:of|edge))",
            re.IGNORECASE,
        ),
        "{neg_place}",
        "",
    ),
    (  # "do not put it anywhere near the front edge": at the other side
        re.compile(
            r"\b(?:do\s+not|never)\s+(?:put|place|build|set|stand)\s+(?:it|them|anything)\s+"
            r"(?:anywhere\s+)?(?:near|close\s+to|next\s+to|by|at|on|in)\s+the\s+"
            r"(left|right|front|back|middle|centre|center)(?:\s+(?:edge|side|half|part|end))?\b",
            re.IGNORECASE,
        ),
        " on the {opposite} ",
        "read '{0}' as on the {opposite}",
    ),
    (  # "it shall not be placed along the front of the table": at the other side
        re.compile(
            r"\b(?:it|they|the\s+\w+)\s+(?:shall|should|must|may|will|is\s+to|are\s+to|can)\s+not\s+"
            r"(?:be\s+)?(?:placed|put|built|set|standing|located|positioned|erected|go)\s+"
            r"(?:anywhere\s+)?(?:on|at|in|along|near|against|by)\s+the\s+(left|right|front|back)"
            r"(?:\s+(?:edge|side|half|part|end))?(?:\s+of\s+the\s+(?:table|workspace|cell|bench))?",
            re.IGNORECASE,
        ),
        " on the {opposite} ",
        "read '{0}' as on the {opposite}",
    ),
    (  # "they don't want it on the left", "but not along the back": at the other side
        re.compile(
            r"(?:\b(?:(?:do|does|did)\s+not|don'?t|doesn'?t)\s+(?:really\s+|particularly\s+)?(?:want|need|"
            r"like)\s+(?:it|them|the\s+\w+|anything)\s+(?:to\s+(?:be|go|stand)\s+)?(?:anywhere\s+)?"
            r"|\b(?:it|they|the\s+\w+)\s+(?:must|should|may|can|shall)\s*(?:not|n'?t)\s+(?:be|go|stand)\s+"
            r"|(?<=[\w\d])\s*,?\s+(?:but\s+)?not\s+(?=along\b)|(?<=[\w\d])\s*,?\s+but\s+not\s+"
            r"|(?<=[\w\d])\s*,?\s+(?:but\s+)?never\s+)"
            r"(?:on|at|in|along|near|against|by)\s+the\s+(left|right|front|back)"
            r"(?:\s+(?:edge|side|half|part|end))?(?:\s+of\s+the\s+(?:table|workspace|cell|bench))?",
            re.IGNORECASE,
        ),
        " on the {opposite} ",
        "read '{0}' as on the {opposite}",
    ),
    (  # "keep it off the front edge", "keep it clear of the left side": at the other side
        re.compile(
            r"\b(?:keep|stay|put|place|set)\s+(?:it|them|everything|the\s+\w+)\s+(?:well\s+)?(?:off|"
            r"away\s+from|clear\s+of)\s+the\s+(left|right|front|back)(?:\s+(?:edge|side|half|end))?\b",
            re.IGNORECASE,
        ),
        " on the {opposite} ",
        "read '{0}' as on the {opposite}",
    ),
    (  # "keep everything in the left half": every structure there
        re.compile(
            r"\b(?:keep|put|place|build)\s+(?:everything|it\s+all|all\s+of\s+it|them\s+all|all\s+of\s+them|"
            r"all\s+(?:the\s+)?structures)\s+(?:in|on|at|to)\s+the\s+(left|right|front|back)"
            r"(?:\s+(?:half|side|part|end))?(?:\s+of\s+the\s+(?:table|workspace|cell|bench))?",
            re.IGNORECASE,
        ),
        "{region_all}",
        "",
    ),
    (  # "not left, not right - in the middle": neither side of that axis
        re.compile(
            r"\b(?:(?:which|that)\s+)?(?:should\s+|must\s+|is\s+|are\s+)?not\s+(?:be\s+)?(?:on\s+|at\s+|in\s+)?"
            r"(?:the\s+)?(left|right|front|back)(?:\s+side)?\s*(?:,|or|nor|and)?\s*(?:not\s+)?"
            r"(?:on\s+|at\s+|in\s+)?(?:the\s+)?(left|right|front|back)(?:\s+side)?\b",
            re.IGNORECASE,
        ),
        "{neither_side}",
        "",
    ),
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
    # "a castle without the corner towers": a ring
    (
        re.compile(
            r"\bcastle\s+(?:without|with\s+no)\s+(?:the\s+|any\s+)?(?:corner\s+)?(?:towers|turrets)\b"
            r"(?:\s+(?:on|at|in)\s+(?:the|its)\s+corners\b)?(?:,?\s*just\s+the\s+walls?(?:\s+around)?)?",
            re.IGNORECASE,
        ),
        " enclosure ",
        "read '{0}' as an enclosure (a castle is a ring with corner towers)",
    ),
    (  # "two stacks, and please no beam on top of them": nothing is added there
        re.compile(
            r",?\s*\b(?:but\s+|and\s+)?(?:please\s+)?(?:no|without\s+(?:a|any))\s+(?:beams?|"
            r"lintels?|planks?|cubes?|blocks?|towers?|roof|top|bridge|anything|nothing)\s+"
            r"(?:across|on\s+top\s+of|on\s+top|onto|on|over|between|above)\s*(?:of\s+)?"
            r"(?:them|it|both|the\s+\w+|each\s+\w+)?(?!\s*(?:'s|\w))",  # not "the top layer's"
            re.IGNORECASE,
        ),
        " ",
        "left out what is not wanted: '{0}'",
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


_CUBE_NOT_ALONE = (
    r"tower|stack|column|pillar|wall|row|line|high|tall|wide|long|deep|thick|taller|shorter|"
    r"higher|lower|wider|longer|deeper|thicker|apart|away|gap|space|spacing|of|from|further|"
    r"farther|closer|more|less|fewer|size|sized|across|per|each|at\s+a\s+time|off|out|in\s+from|"
    r"to\s+(?:the\s+)?(?:left|right|front|back)(?!\s+of)|back|forward|forwards|backwards|"
    r"left|right|up|over|along|shy|short|in\s+size|and\s+a\s+half|"
    r"to|could|can|would|will|might|should|must|fits?|"
    r"pass(?:es)?|goes|gets"
)
"""A word after "a cube" that makes it a unit or a part of a structure, not a loose cube."""

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


_ENCLOSURES = "|".join(
    sorted((w for w, f in lx.SHAPE_WORDS.items() if f == "enclosure" and w.isalpha()), key=len)
)
_SHAPE_ALT = shape_alternation()
# structure nouns that are never a part of another ("2 more steps" adds to a staircase)
_STRUCTURE_ALT = "|".join(
    sorted(
        (w for w in lx.SHAPE_WORDS if w.isalpha() and w not in lx.STEP_WORDS
         and not re.fullmatch(r"(?:row|layer|level|course|tier|stair|step|flight)s?", w)),
        key=len, reverse=True,
    )
)  # fmt: skip
# a singular structure noun followed by its size ("tower 3 high", "row of 5 long")
_COUNTED_NOUN = (
    r"(tower|stack|column|row|wall|pyramid|bridge|staircase|slab|pad|block|ring|arch)\s+"
    r"(?=(?:of\s+)?\d+\s*(?:cubes?\s+)?(?:high|tall|long|wide|levels?|steps?|x)\b)"
)
_NUMBER_WORD = "one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve"
_COUNTED = r"(?:steps?|levels?|layers?|towers?|rows?|blocks?|stacks?|columns?)"
"""What a count is said of in "one step fewer than 5" (kept with the number worked out)."""
_GLOSS_LEAD = r"(?:(?:so\s+|that\s+is\s+|i\.?e\.?\s+)?(?:going|running|measured|counted)\s+)?"


_REWRITES += [
    # "anywhere except the back", "anywhere but on the left", "avoid the left side"
    (
        re.compile(
            r"\b(?:anywhere\s+but|(?:anywhere\s+)?(?:except|but\s+not|other\s+than|apart\s+from|"
            r"away\s+from|avoid(?:ing)?))\s+(?:on\s+|in\s+|at\s+)?the\s+(left|right|front|back|"
            r"middle|centre|"
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
            # "a tower on each side": the table's; "a wall with a tower on each side": the wall's
            r"(?<!\bwith\s)\b(one|a)\s+(\w+)(\s+of\s+\d+)?\s+on\s+each\s+side(?:\s*,?\s*(?:the\s+)?left\s+and\s+"
            r"(?:the\s+)?right)?\b(?!\s+of\s+(?:it|them|the|that|this)\b)",
            re.IGNORECASE,
        ),
        " {0} {1}{2} on the left and another {1}{2} on the right ",
        "",
    ),
    # "a staircase that does not go up towards the back", "do not make them go towards me": it
    # climbs the other way (or the way said elsewhere)
    (
        re.compile(
            r",?\s*\b(?:but\s+)?(?:that\s+|which\s+|and\s+)?(?:they\s+|it\s+)?(?:(?:does|do|must|"
            r"should|may|shall)\s+not|not|never)\s+(?:make\s+(?:it|them)\s+)?(?:go(?:ing)?\s+up|"
            r"going|climbing|rising|go|climb|rise|ascend|lead\s+up)"
            r"\s+(?:towards?|to)\s+(?:the\s+(back|front|left|right)|(me|us|the\s+robot))\b",
            re.IGNORECASE,
        ),
        "{not_climb}",
        "",
    ),
    (  # "three towers going up by one each starting at two": 2, 3 and 4
        re.compile(
            r"\b(?P<n>\d+|two|three|four|five|six)\s+(?P<kind>towers|stacks|columns|pillars)\s*,?\s*"
            r"(?:going\s+up|rising|climbing|increasing|growing|getting\s+(?:taller|higher|bigger))"
            # "… getting taller from left to right, starting at 1": one more each, unsaid
            r"(?:\s+by\s+(?P<step>\d+|one|two|a)(?:\s+cubes?)?(?:\s+each(?:\s+time)?)?)?"
            r"(?P<dir>\s+from\s+(?:the\s+)?(?:left\s+to\s+(?:the\s+)?right|right\s+to\s+(?:the\s+)?left|"
            r"front\s+to\s+(?:the\s+)?back|back\s+to\s+(?:the\s+)?front))?"
            r"\s*,?\s*(?:and\s+)?(?:starting|beginning)\s+"
            r"(?:at|from|with)\s+(?P<first>\d+|one|two|three|four|five)(?:\s+cubes?)?"
            r"(?:\s+(?:high|tall))?\b",
            re.IGNORECASE,
        ),
        "{series}",
        "",
    ),
    (  # "three towers of 2, 4 and 6, ascending from right to left": taller towards the left
        re.compile(
            r",?\s*\b(?:ascending|rising|climbing|increasing|growing|getting\s+taller|going\s+up)"
            r"(?:\s+in\s+height)?\s+from\s+(?:the\s+)?(left|right|front|back)\s+to\s+(?:the\s+)?"
            r"(left|right|front|back)\b",
            re.IGNORECASE,
        ),
        "{rise_order}",
        "",
    ),
    (
        re.compile(
            r",?\s*\b(?:(?:climbing|rising|ascending|going|stepping)\s+up|climbing|rising|"
            r"(?:make\s+(?:it|them)\s+)?(?:go|goes)\s+up|"
            r"ascending|(?:it\s+|they\s+)?(?:to\s+)?(?:climbs?|rises?|ascends?|rose|climbed|ascended|"
            r"went\s+up)(?:\s+up)?)\s+"
            r"(?:to(?:wards)?|toward|to\s+the)\s+(?:the\s+|my\s+|your\s+|our\s+)?"
            r"(left|right|front|back)\b|,?\s*\bup\s+to(?:wards)?\s+the\s+(left|right|front|back)\s+"
            r"(?:climbing|rising|ascending|going)\b",
            re.IGNORECASE,
        ),
        "{climb}",
        "",
    ),
    (  # "stairs x4, up to the back": the way a staircase named just before climbs
        re.compile(
            r"((?:\bstairs|\bsteps|\bstaircase)(?:\s+(?:x\s*|of\s+)?(?:\d+|two|three|four|five|six|"
            r"seven|eight)(?:\s+steps)?)?)\s*,?\s*(?:going\s+)?up\s+to(?:wards)?\s+the\s+"
            r"(left|right|front|back)\b",
            re.IGNORECASE,
        ),
        "{stairs_up}",
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
    # "a tower of 3 and a cube to its left", "… and a cube 10 cm behind it": a cube added (not
    # "a cube to the left", a distance)
    (
        re.compile(
            r"(?<=\band\s)(a|an)\s+(?:cube|brick)\s+(?=(?:\d+(?:\.\d+)?\s*(?:cm|mm|m)\s+)?"
            r"(?:to\s+(?:its|the)\s+(?:left|right)|in\s+front\s+of|behind|next\s+to|beside)\b)",
            re.IGNORECASE,
        ),
        " {0} 1-cube tower ",
        "",
    ),
    # "a cube at the back left and a cube at the front right", "stack a second cube on it": a
    # loose cube is a structure of its own (not a unit: "a cube high", "a cube's width", "a cube
    # of space", "a cube tower")
    (
        re.compile(
            r"\b(a|an)\s+(?:(?:second|third|fourth|further|extra|additional|spare)\s+)?"
            r"(?:cube|brick)\b(?!'|\s*(?:-|" + _CUBE_NOT_ALONE + r")\b)",
            re.IGNORECASE,
        ),
        " {0} 1-cube tower ",
        "",
    ),
    (
        re.compile(
            r"\b(one|1)\s+(?:lonely\s+|lone\s+|little\s+|small\s+|extra\s+)?(?:cube|brick|block)\s+"
            r"(?=(?:on|at|in|inside|near|beside|by|into)\s+(?:the|its|their|a|top|"
            r"(?:each|every)(?!\s*(?:[.!,;]|$)))\b|"
            r"(?:sitting|standing|resting)\b)",
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
    (  # "then stack 2 more on the middle one": a column of 2 standing on its middle
        re.compile(
            r"\b(?:stack|put|add|place|pile)\s+(\d+|two|three|four|five|six)\s+(?:more\s+)?(?:cubes?\s+)?"
            r"on\s+(?:top\s+of\s+)?(?:the\s+)?(?:middle|centre|center)(?:\s+(?:one|cube|part))?"
            r"(?:\s+of\s+(?:it|them))?",
            re.IGNORECASE,
        ),
        " a tower of {0} on top of it ",
        "read '{0}' as a column on its middle",
    ),
    (
        re.compile(r"\bon\s+(?:its|the)\s+(?:centre|center|middle|top)\b(?:\s+(?:cube|part|brick)\b(?!\s+of\b))?"
                   r"(?!\s+(?:of|one|tower|stack|column|block|slab|pillar|wall|row)\b)", re.I),
        " on top ",
        "",
    ),
    (  # "no taller than 7 inches, but as tall as that allows": the bound's most, built
        re.compile(
            r",?\s*\b(?:but\s+|and\s+)?(?:as\s+(?:tall|high|big|long)\s+as\s+(?:that|it|this|"
            r"the\s+(?:limit|bound|rule))\s+(?:allows|permits|lets\s+(?:it|you|me|us))|"
            r"as\s+(?:tall|high)\s+as\s+(?:allowed|permitted))\b",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': the most the bound allows, as built",
    ),
    (  # "sitting right up at the back edge, within an inch of it": flush, as built
        re.compile(
            r"(?<=edge)(?:[^.;]{0,40}?),?\s*\bwithin\s+(?:a\s+|an\s+)?\d+(?:\.\d+)?\s*(?:mm|cm)\s+of\s+"
            r"(?:it|that|the\s+(?:\w+\s+)?edge)\b",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': the structure stands flush against the edge, within that",
    ),
    (  # "perpendicular to the front edge": running front to back
        re.compile(r"\bperpendicular\s+to\s+the\s+(front|back)(?:\s+(?:edge|side))?\b", re.I),
        " running front to back ",
        "read '{0}' as running front to back",
    ),
    (
        re.compile(r"\bperpendicular\s+to\s+the\s+(left|right)(?:\s+(?:edge|side))?\b", re.I),
        " running left to right ",
        "read '{0}' as running left to right",
    ),
    (  # "a square of 4 by 4 blocks, only the edge": a ring
        re.compile(
            r",?\s*\b(?:only|just)\s+(?:the\s+)?(?:edge|edges|border|outline|rim|outside|perimeter)\b"
            r"(?:\s+of\s+it)?",
            re.IGNORECASE,
        ),
        " hollow ",
        "read '{0}' as hollow, a ring",
    ),
    (  # "stand a 2-high stack in its centre well", "in position B2 of a 3 x 3 plate": on it
        re.compile(
            r"\b(?:in|into|on|at)\s+(?:its|the)\s+(?:centre|center|middle|central)\s+(?:well|position|"
            r"hole|spot|slot|cell)\b",
            re.IGNORECASE,
        ),
        " on top of it ",
        "read '{0}' as on top of it, centred",
    ),
    (  # "in position B2 of a 3 x 3 plate": on top of the plate, at that position
        re.compile(
            r"\b(?:in|at|on|into)\s+(?:position|well|slot|cell)\s+([A-H])(\d{1,2})\s+(?:of|on|in)\s+"
            r"(a|an|the|its|this)\s+(?=(?:(\d+)\s*(?:x|by)\s*(\d+)\s+)?)",
            re.IGNORECASE,
        ),
        "{plate_position}",
        "",
    ),
    (  # "like position A1 on a plate": a likeness, not a place of its own
        re.compile(
            r",?\s*\b(?:just\s+)?like\s+(?:position|well|slot|cell)\s+[A-Z]\d+(?:\s+(?:on|of|in)\s+(?:a|the)\s+"
            r"(?:plate|rack|grid|tray|board))?",
            re.IGNORECASE,
        ),
        " ",
        "read '{0}' as a description, not a place",
    ),
    (  # "near to wall on back", "against the back wall" (no wall named): the table's edge
        re.compile(
            r"\b(?:near|by|against|along|at|next\s+to|close\s+to)\s+(?:the\s+)?(?:wall\s+(?:on|at)\s+(?:the\s+)?"
            r"(back|front|left|right)|(back|front|left|right)\s+wall)\b",
            re.IGNORECASE,
        ),
        "{wall_edge}",
        "",
    ),
    (  # "four towers; first from 1 cube, every next one cube higher": 1, 2, 3 and 4
        re.compile(
            r"\b(\d+|two|three|four|five|six)\s+(towers|stacks|columns|pillars)\s*[;:,]?\s*(?:the\s+)?first\s+"
            r"(?:of|from|with|is|one)?\s*(\d+)(?:\s+cubes?)?(?:\s+(?:high|tall))?\s*,?\s*(?:and\s+)?(?:every|each)\s+(?:next|"
            r"following|other|subsequent)(?:\s+one)?\s+(\d+|one|two|a)\s+(?:cubes?\s+)?(?:higher|taller|more)\b",
            re.IGNORECASE,
        ),
        "{progression}",
        "",
    ),
    (  # "four towers, one of each height from one to four": 1, 2, 3 and 4
        re.compile(
            r"\b(?P<n>\d+|two|three|four|five|six)\s+(?P<kind>towers|stacks|columns|pillars)\s*,?\s*"
            r"one\s+(?:of\s+)?each\s+(?:height|size)\s+from\s+(?P<first>\d+|one|two|three|four|five)"
            r"\s+(?:to|through|up\s+to)\s+(?P<last>\d+|two|three|four|five|six|seven|eight|nine|ten)\b",
            re.IGNORECASE,
        ),
        "{series}",
        "",
    ),
    (  # "three towers, starting at 2 and each one cube taller than the one before": 2, 3, 4;
        # "three towers: start with 2 cubes and add one more cube for every next tower"
        re.compile(
            _SERIES_LEAD
            + r"(?:and\s+)?(?:then\s+)?(?:(?:each|every)\s+(?:(?:next|following|subsequent)\s+)?"
            r"(?:one|tower|stack|column)?\s*(?:is\s+)?(?P<step>\d+|one|two|a)\s+(?:more\s+)?(?:cubes?\s+)?"
            r"(?:taller|higher|more)(?:\s+than\s+the\s+(?:one|last|previous)(?:\s+one)?(?:\s+before"
            r"(?:\s+it)?)?)?)",
            re.IGNORECASE,
        ),
        "{series}",
        "",
    ),
    (
        re.compile(
            _SERIES_LEAD
            + r"(?:and\s+)?(?:then\s+)?add(?:ing)?\s+(?P<step>\d+|one|two|a)\s+(?:more\s+)?"
            r"cubes?\s+(?:for|to|on|with)\s+(?:each|every)\s+(?:next|following|subsequent|further)\s+"
            r"(?:one|tower|stack|column)\b",
            re.IGNORECASE,
        ),
        "{series}",
        "",
    ),
    (  # "a pyramid …, but stop before the single top cube": a top left off, which SDI cannot
        re.compile(
            r",?\s*\b(?:but\s+)?stop\s+(?:before|short\s+of)\s+(?:the\s+|its\s+)?(?:single\s+|very\s+)?"
            r"(?:top|last)(?:\s+(?:cube|level|layer|one|tier))?\b",
            re.IGNORECASE,
        ),
        "{unmade}",
        "",
    ),
    (  # "in a line, symmetric about the middle of the table": a line stands centred anyway
        re.compile(
            r",?\s*\bsymmetric(?:al(?:ly)?)?\s+(?:about|around|on|across)\s+(?:the\s+)?(?:middle|centre|"
            r"center)(?:\s+line)?(?:\s+of\s+the\s+(?:table|workspace|cell))?",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': the structures stand centred on the table",
    ),
    (  # "so that a ball can be kept inside", "so the dolls can walk across": what it is for
        # (its words were read as a structure to enclose, or reported unused)
        re.compile(
            r"\s*,?\s*\b(?:so\s+that|so|in\s+order\s+that)\s+(?:a|an|the|my|our|his|her|their|it|we|they|he|"
            r"she|you|i|people|kids|children)\b(?:\s+\w+){0,3}?\s+(?:can|could|will|would|may|might|fits?|"
            r"stays?|remains?|does\s+not|doesn't|won't|cannot|can't)\b"
            r"[^.,;!?\d]*(?=[.,;!?]|$)",
            re.IGNORECASE,
        ),
        " ",
        "ignored '{0}': what it is for, not how to build it",
    ),
    (  # "a wall 5 long. put one more block on top at each end": a single cube (a 2x2x2 block
        # fell off the wall: failure), unless a tower named last grows by it
        re.compile(r"\b(?:one\s+more|an\s+extra|one\s+extra|another)\s+(?:single\s+)?(?:cube|block|brick)"
                   r"(?=\s+(?:on|onto|up)\b)", re.IGNORECASE),
        "{extra_cube}",
        "",
    ),
    (  # "I need two things. A pyramid with 3 levels …": how many structures follow, said in a
        # sentence of its own (its "two" sized the pyramid: a base of 2, failure); checked
        # against the structures built
        re.compile(
            r"(?:^|(?<=[.;:!?]))\s*(?:(?:so\s+|ok(?:ay)?\s*,?\s*)?(?:i|we)\s+(?:need|want|would\s+like)\s+|"
            r"(?:please\s+)?(?:build|make)\s+(?:me\s+|us\s+)?|there\s+(?:are|will\s+be)\s+)?"
            r"(?:two|three|four|five|[2-5])\s+(?:different\s+|separate\s+|small\s+|little\s+)?"
            r"(?:things|structures|items|objects|shapes|builds|models)\s*(?:[.;!]|:(?!\s*$))",
            re.IGNORECASE,
        ),
        " ",
        "",
    ),
    (  # "Grid of 2 by 5. Flat. Put it on the right.": a word of the structure before, said as
        # a sentence of its own ('Flat' named no structure: partial)
        re.compile(
            r"(?<=\w)\s*[.;!]\s+((?:(?:it\s+(?:should|must)\s+be|keep\s+it|make\s+it)\s+)?(?:flat|"
            r"(?:just\s+|only\s+)?(?:one|a\s+single|single)\s+(?:layer|level)(?:\s+(?:high|thick|deep))?"
            r"(?:\s+only)?))\s*(?=[.;!]|$)",
            re.IGNORECASE,
        ),
        ", {0}",
        "",
    ),
    (  # "an L shape of 5 by 3 with a tower of 4 at the corner": on the L's own corner
        re.compile(
            r"\s*,?\s*\b(?:standing\s+|sitting\s+|placed\s+)?(?:at|on|in)\s+(?:the|its)\s+"
            r"(?:inner\s+|inside\s+|outer\s+)?corner\b(?!\s+of\s+the\s+(?:table|workspace|cell|bench|"
            r"work\s*area|area)\b)(?:\s+of\s+(?:it|the\s+l(?:[\s-]?shape)?))?",
            re.IGNORECASE,
        ),
        "{bend}",
        "",
    ),
    (  # "a pyramid like the ones in Egypt": a likeness, with no size or place in it
        re.compile(
            r"\s*,?\s*\blike\s+(?:the\s+ones?|those|the\s+one|that\s+one)\s+(?:in|at|from|of)\s+(?:the\s+)?"
            r"[a-z]+(?:\s+[a-z]+)?(?=\s*(?:[,.;!?]|$))",
            re.IGNORECASE,
        ),
        " ",
        "ignored '{0}': a likeness, with no size or place in it",
    ),
    (  # "a lonely staircase …, away from everything": apart, as separate structures stand
        # anyway ("away" turned the staircase to climb to the back, silently)
        re.compile(
            r"\s*,?\s*\b(?:well\s+|far\s+)?away\s+from\s+(?:everything|anything|all\s+else|the\s+rest|"
            r"the\s+others|other\s+things)(?:\s+else)?\b",
            re.IGNORECASE,
        ),
        " ",
        "read '{0}' as standing apart (separate structures always do)",
    ),
    (  # "…, touching it, like the gable end of a house": a likeness said last (the house was
        # built as a ring)
        re.compile(
            r"\s*,\s*(?:a\s+bit\s+|just\s+|kind\s+of\s+)?like\s+(?:a|an|the)\s+(?:[a-z]+\s+){1,3}of\s+"
            r"(?:a|an|the|some)\s+[a-z]+(?:\s+[a-z]+)?(?=\s*(?:[.;!?]|$))",
            re.IGNORECASE,
        ),
        " ",
        "ignored '{0}': a likeness, with no size or place in it",
    ),
    (  # "0.25 m ±0.01 tall": a tolerance said without its unit (read as a count of its own,
        # "0.01 is not a usable count")
        re.compile(
            r"\s*(?:±|\+\s*/\s*-|\+-|plus\s+or\s+minus)\s*\d+(?:\.\d+)?\b(?!\s*(?:mm|cm|m)\b)"
            r"(?:\s+(?:tolerance|tol\.?))?",
            re.IGNORECASE,
        ),
        " ",
        "read '{0}' as a tolerance: the parts stand at the value said",
    ),
    (  # "a cross with arms 2 cubes long": each arm from the middle, a bar of 5
        re.compile(
            r"\b(?:cross|plus(?:\s+sign)?)(?:[\s-]*(?:lap[\s-]+)?shape[ds]?(?:\s+\w+)?)?(?:\s+(?:made|built)\s+(?:of|"
            r"from|out\s+of)\s+(?:\w+\s+)?(?:cubes?|blocks?))?(?:\s*,[^.;:,]{0,30},(?:[^.;:,]{0,20},)?)?"
            r"\s*[,?.!:;\u2014\u2013-]?\s+(?:with\s+)?(?:(?:its|the)\s+)?"
            r"(?:arms?(?:\s+length)?|each\s+arm)\s+(?:(?:are|is)\s+)?(?:of\s+)?(\d+|one|two|three|four)(?:\s*(?:cubes?|"
            r"blocks?)\b|\s*(mm|cm|m)\b)?(?:\s+long\b)?(?:\s+each\b)?(?:(?:\s+out)?(?:\s+from\s+the\s+(?:centre|"
            r"center|middle)(?:\s+(?:cube|block))?)|\s+out\b)?",
            re.IGNORECASE,
        ),
        "{cross_arms}",
        "",
    ),
    # "16 inches out from the robot", "8 inches left of the middle line": a coordinate
    (
        re.compile(
            r"\b(?:about\s+|around\s+|roughly\s+|some\s+)?(\d+(?:\.\d+)?)\s*(mm|cm|m)\s+(?:(?:(?:out|away)\s+)?"
            r"from\s+the\s+robot(?:'s\s+base|\s+base)?|(?:to\s+the\s+)?(left|right)\s+of\s+the\s+"
            r"(?:middle|centre|center)(?:[\s-]*line)?|(in\s+front\s+of|behind)\s+the\s+(?:middle|centre|"
            r"center)(?:[\s-]*line)?)\b",
            re.IGNORECASE,
        ),
        "{offset}",
        "",
    ),
    # "no taller than 177.8 mm", "at most 18 cm high": the whole parts within the bound
    (
        re.compile(
            r"(?:,\s*)?\b(?:but\s+)?(?:(?:no|not|never)\s+(?:taller|higher)\s+than\s+"
            r"(\d+(?:\.\d+)?)\s*(mm|cm|m)\b(?:\s+(?:tall|high))?|(?:at\s+most|no\s+more\s+than|"
            r"not\s+more\s+than|max(?:imum)?(?:\s+of)?)\s+(\d+(?:\.\d+)?)\s*(mm|cm|m)\s+"
            r"(?:tall|high|in\s+height)\b)",
            re.IGNORECASE,
        ),
        "{within}",
        "",
    ),
    # "no taller than 2 cubes" → 2 cubes high; "no more than 3 steps" → 3 steps
    (
        re.compile(
            r"\b(?:no|not|nothing|none)\s+(?:taller|higher)\s+than\s+(\d+|[a-z]+)"
            r"(\s*(?:cubes?|parts?|blocks?|levels?|layers?|cm|mm|m|centimet(?:er|re)s?|"
            r"millimet(?:er|re)s?|met(?:er|re)s?|inch(?:es)?|in|foot|feet|ft)\b)?",
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
    # "a tower at the back, not the front": the place that is not wanted
    (
        re.compile(
            r"\b(left|right|front|back|rear)(\s+(?:side|half|end|edge|corner))?\s*,?\s*"
            r"(?:but\s+|and\s+)?not\s+(?:on\s+|at\s+|in\s+|to(?:wards)?\s+)?(?:the\s+)?"
            r"(?:left|right|front|back|rear|middle|centre|center)(?:\s+(?:side|half|end|edge))?\b"
            r"(?!\s+(?:of|left|right)\b)",
            re.IGNORECASE,
        ),
        "{0}{1} ",
        "'{0}': kept the other place",
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
            r"\b(grid|square|layer|slab|pad|patch|platform|block|deck|floor|plate|mat)\b([^.;]{0,30}?)"
            r"\s*,?\s*(?:without|minus|"
            r"but\s+not|except(?:\s+for)?|leave\s+out|leaving\s+out|leave\s+off)\s+(?:the\s+|a\s+|its\s+)?"
            r"(?:middle|centre|center|inner|central)(?:\s+(?:cubes?|ones?|parts?|pieces?|column|blocks?|"
            r"bricks?))?",
            re.IGNORECASE,
        ),
        " hollow {0} {1} ",
        "read '{0}' as a hollow ring",
    ),
    (  # "a 5 by 5 deck, but leave the middle open": a ring too
        re.compile(
            r"\b(grid|square|layer|slab|pad|patch|platform|block|deck|floor|plate|mat)\b([^.;]{0,30}?)"
            r"\s*,?\s*(?:but\s+|and\s+)?(?:leave|leaving|keep|keeping)\s+(?:the\s+|its\s+)?(?:middle|"
            r"centre|center|inside|interior)(?:\s+(?:cubes?|ones?|parts?|bit|square|area))?\s+(?:open|empty|"
            r"free|clear|hollow|out|unfilled)\b",
            re.IGNORECASE,
        ),
        " hollow {0} {1} ",
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
    # "not a 3-D one, just flat" for pyramids
    (
        re.compile(
            r",?\s*\b(?:but\s+)?not\s+(?:a\s+)?3-?d(?:\s+one)?,?(?:\s+just)?(?:\s+flat)?", re.I
        ),
        " 2-D ",
        "read '{0}' as a flat (2-D) one",
    ),
    # "my son says no bridges and no towers today": what is not wanted, said as someone's wish
    (
        re.compile(
            r"\b(?:says?|said|wants?|asks?\s+for|asked\s+for)\s+no\s+(?:more\s+)?(?:" + _SHAPE_ALT
            + r")(?:\s*(?:,|and|or|nor)\s*no\s+(?:more\s+)?(?:" + _SHAPE_ALT
            + r"))*\s+(?:this\s+time|today|now|tonight|please)\b",
            re.IGNORECASE,
        ),
        " ",
        "left out what is not wanted: '{0}'",
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
    # "as tall a tower as possible" → the tallest tower
    (
        re.compile(
            r"\bas\s+(?:tall|high)\s+an?\s+(\w+)\s+as\s+(?:possible|it\s+can\s+(?:go|get|be)|"
            r"you\s+can(?:\s+(?:make|build|go|get|manage|do|stack))?|"
            r"the\s+(?:cell|workspace|space|robot)\s+(?:allows|permits))",
            re.IGNORECASE,
        ),
        " a {0} , tallest , ",
        "read '{0}' as the tallest that fits",
    ),
    # "as tall as the cell allows" → the tallest
    (
        re.compile(
            r"\bas\s+(tall|high)\s+as\s+(?:the\s+(?:cell|workspace|space|robot|room)\s+"
            r"(?:allows|permits|can\s+\w+)|possible|it\s+can\s+(?:go|get|be)|you\s+can(?:\s+\w+)?|"
            r"allowed)",
            re.IGNORECASE,
        ),
        " tallest , ",
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
    # "six cubes in one column, please stack", "a tower of 5, build it please": a verb left at
    # the end of a clause names no structure of its own
    (
        re.compile(
            r"(?:,|\band\b|\bplease\b|\bthen\b|\bnow\b)\s*(?:please\s+|now\s+|just\s+)?"
            r"(?:build|make|do)(?:\s+(?:it|please|now|away))*(?=\s*(?:[.!?;]|$))",
            re.IGNORECASE,
        ),
        " ",
        "",
    ),
    (  # "cubes six, in one column, please stack": said of the parts, the verb is how they stand
        re.compile(
            r"(?:,|\band\b|\bplease\b|\bthen\b|\bnow\b)\s*(?:please\s+|now\s+|just\s+)?"
            r"(?:stack|pile)(?:\s+(?:it|up|'em|please|now|them\s+up))*(?=\s*(?:[.!?;]|$))",
            re.IGNORECASE,
        ),
        ", stacked ",
        "",
    ),
    # "4 rows, 3 cubes per row", "4 rows and 3 columns": rows of that many
    (
        re.compile(
            r"\b(\d+|"
            + _NUMBER_WORD
            + r")\s+rows?\s*,?\s*(?:with\s+|of\s+)?(\d+|"
            + _NUMBER_WORD
            + r")\s+(?:cubes?|blocks?|parts?|bricks?)\s+"
            r"(?:per|in\s+each|each|a|in\s+every|for\s+each)\s+row\b|\b(\d+|"
            + _NUMBER_WORD
            + r")\s+rows?\s+(?:and|by|x|with)\s+(\d+|"
            + _NUMBER_WORD
            + r")\s+columns?\b",
            re.IGNORECASE,
        ),
        "{rows_of}",
        "",
    ),
    # "a grid of 4 rows of 3", "a slab with 2 rows of 5": the rows are the floor, not a second
    (
        re.compile(
            r"\b(?:a\s+|an\s+|one\s+|the\s+)?(?:grid|slab|pad|floor|platform|layer|mat|patch|"
            r"rectangle)\s+(?:of|with|made\s+(?:of|from)|in|having)\s+(?=(?:\d+|"
            + _NUMBER_WORD
            + r")\s+rows?\s+of\b)",
            re.IGNORECASE,
        ),
        " ",
        "",
    ),
    # "2 cubes deep (away from the robot)", "5 wide, left to right": a gloss that says what
    # depth or width is already means it; it does not turn the structure
    (
        re.compile(
            r"\b(deep|in\s+depth)\s*[(,-]?\s*" + _GLOSS_LEAD + r"(?:away\s+from\s+(?:the\s+)?"
            r"(?:robot|me|you|us)|(?:from\s+)?front\s+to\s+back|(?:from\s+)?back\s+to\s+front|"
            r"towards?\s+the\s+back)\s*\)?",
            re.IGNORECASE,
        ),
        " {0} ",
        "",
    ),
    (
        re.compile(
            r"\b(wide|in\s+width)\s*[(,-]?\s*" + _GLOSS_LEAD + r"(?:(?:from\s+)?left\s+to\s+right|"
            r"(?:from\s+)?right\s+to\s+left|across(?:\s+the\s+(?:table|robot))?|sideways)\s*\)?",
            re.IGNORECASE,
        ),
        " {0} ",
        "",
    ),
    (  # "one cube on the top of all": on top of the last, the highest
        re.compile(
            r"\bon\s+(?:the\s+)?(?:very\s+)?top\s+of\s+(?:all|everything|it\s+all|all\s+of\s+it|"
            r"the\s+whole\s+thing|the\s+lot|all\s+that|them\s+all|all\s+of\s+them)\b",
            re.IGNORECASE,
        ),
        " on top ",
        "",
    ),
    (  # "a walled area", "a fenced yard": a ring
        re.compile(
            r"\b(?:walled|fenced)(?:[\s-]+in)?\s+(?:area|space|yard|court|garden|square|"
            r"plot|zone|region)\b",
            re.IGNORECASE,
        ),
        " enclosure ",
        "read '{0}' as an enclosure",
    ),
    (  # "three stacks, each one 4 inches high": each of them
        re.compile(r"\beach\s+one\s+(?=\d|(?:" + _NUMBER_WORD + r")\b)", re.IGNORECASE),
        " each ",
        "",
    ),
    (  # "half a dozen of the 2-inch blocks": the size of the cell's own parts, said
        re.compile(
            r"\b(?:of\s+)?(?:the|these|those|our)\s+(\d+(?:\.\d+)?)\s*(mm|cm)\s+(cubes?|blocks?|bricks?)\b",
            re.IGNORECASE,
        ),
        "{part_size}",
        "",
    ),
    (  # "two columns of 4, joined at the top": towers joined at the top are a bridge's pillars
        re.compile(
            r"\b(towers|pillars|columns|stacks|posts)\b([^.;]*?)(?<!\bnot\s)(?<!n't\s)(?<!\bnever\s)"
            r"\b(?:joined|connected|linked|"
            r"bridged|tied)\s+(?:together\s+)?(?:at|across|along|over)\s+(?:the\s+)?tops?\b"
            r"(?!\s+(?:by|with))",
            re.IGNORECASE,
        ),
        "{0}{1} joined at the top by a beam ",
        "read '{0}' as the towers joined by a beam across the top",
    ),
    (  # "two towers of 5, then a beam across the top", "… beam across.": the beam lies on top
        # of what was said before it (read as a beam 'across' a structure named "the top")
        re.compile(
            r"\b(beams?|lintels?|planks?|girders?|crossbars?)\s+(?:(?:laid|lying|running|placed|"
            r"set|going|resting)\s+)?(?:across|over|spanning)(?:\s+(?:the|their|both)(?:\s+two)?"
            r"\s+tops?|\s+(?:the\s+)?top)?(?=\s*(?:[.;,)]|$|\b(?:then|and|like|as)\b))",
            re.IGNORECASE,
        ),
        "{0} on top ",
        "",
    ),
    (re.compile(r"\b(?:on|at)\s+the\s+(?:very\s+)?top\b(?!\s+of)", re.IGNORECASE), " on top ", ""),
    (  # "two towers of 3, beam on top": a part of its own after the comma (read as the towers'
        # own word, one tower stood on the other)
        re.compile(
            r"\s*,\s*(?:and\s+)?(?:(?:a|the|one)\s+)?(?:(?:long|single|flat)\s+)?(beam|lintel|"
            r"plank|girder|crossbar)\s+on\s+top\b(?!\s+of|\s+(?:joining|connecting|linking|"
            r"spanning|bridging)\b)",
            re.IGNORECASE,
        ),
        ". a {0} on top",
        "",
    ),
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
    (  # "a row of 5 with a cube on each cube", "and on every cube of it another cube": a layer
        re.compile(
            r"\s*,?\s*\b(?:with|and|then|plus)\s+(?:(?:put|place|stack|add)\s+)?(?:another\s+|a\s+|one\s+)?"
            r"(?:single\s+|second\s+)?(?:1-cube\s+tower|cube|block)\s+(?:on(?:\s+top\s+of)?|above|onto)\s+(?:each|every)\s+"
            r"(?:single\s+)?(?:cube|one|part|block)(?:\s+of\s+(?:it|them|that))?"
            r"|\s*,?\s*\b(?:and|then)\s+(?:put\s+|place\s+|stack\s+)?on\s+(?:top\s+of\s+)?(?:each|every)\s+"
            r"(?:single\s+)?(?:cube|one|part|block)(?:\s+of\s+(?:it|them|that))?\s*,?\s*(?:another|a|one)\s+"
            r"(?:more\s+)?(?:cube|block)\b",
            re.IGNORECASE,
        ),
        ", then add another layer on top ",
        "read '{0}' as another layer on top",
    ),
    (  # "a T with a 5 long top and a 3 long stem": the part of that length
        re.compile(
            r"\b(?:a|an|one)\s+(\d+)[- ](?:cubes?[- ])?(?:long|wide)\s+"
            r"(top|stem|bar|crossbar|base)\b",
            re.IGNORECASE,
        ),
        " a {1} of {0} ",
        "",
    ),
    (
        re.compile(
            r"\b(?:a|an|one)\s+(\d+)[- ](?:cubes?[- ])?(?:long|wide)\s+(arm|upright)\b",
            re.IGNORECASE,
        ),
        " an {1} of {0} ",
        "",
    ),
    (  # "an arm of 4 and an arm of 2", "one arm of 4 and another arm of 2": the arms 4 and 2
        re.compile(
            r"\b(?:an|one)\s+arm\s+of\s+(\d+)(?:\s+cubes?)?\s*,?\s+and\s+(?:an|one|another|the\s+other)"
            r"\s+arm\s+of\s+(\d+)(?:\s+cubes?)?",
            re.IGNORECASE,
        ),
        " arms {0} and {1} ",
        "",
    ),
    (  # "a tower of 5 but leave off the top cube", "… without the top layer": taken off after
        re.compile(
            r"(?<=[a-z0-9])\s*,?\s*(?:but\s+|and\s+|only\s+)?(?:leave\s+(?:off|out)|leaving\s+(?:off|out)|"
            r"without|minus|less|omit(?:ting)?|skip(?:ping)?|drop(?:ping)?)\s+the\s+"
            r"((?:top|upper|uppermost|highest|last)\s+(?:(?:one|two|three|\d)\s+)?"
            r"(?:cubes?|blocks?|layers?|levels?|courses?|rows?|steps?|tiers?))\b",
            re.IGNORECASE,
        ),
        ", then remove the {0} ",
        "",
    ),
    (
        re.compile(
            r"\b(?:but\s+|and\s+)?(?:do\s+not|never)\s+(?:put|place|build|set)\s+(?:it|them)\s+"
            r"(?:on|in|at|to)\s+the\s+(left|right|front|back|middle|centre|center)(?:\s+side)?\b",
            re.IGNORECASE,
        ),
        " on the {opposite} ",
        "read '{0}' as on the {opposite}",
    ),
    (  # "don't use the left half of the table", "stay out of the back part"
        re.compile(
            r",?\s*\b(?:(?:but\s+|and\s+)?(?:do\s+not|never|must\s+not|cannot|can\s+not)\s+"
            r"(?:use|touch|go\s+(?:into|in|on)|build\s+(?:on|in)|put\s+anything\s+(?:on|in))|"
            r"(?:and\s+)?(?:stays?|keep(?:s|ing)?(?:\s+(?:it|them|everything))?)\s+out\s+of)\s+the\s+"
            r"(left|right|front|back|middle|centre|center)(?:\s+(?:half|side|part|end|quarter|third|"
            r"strip|edge))?(?:\s+of\s+the\s+(?:table|workspace|work\s+area|cell|bench))?\b",
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
            r"(\s*(?:cubes?|parts?|blocks?|levels?|layers?|cm|mm|m|centimet(?:er|re)s?|"
            r"millimet(?:er|re)s?|met(?:er|re)s?|inch(?:es)?|in|foot|feet|ft)\b)?",
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
        "{maybe}",
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
            r"(?:\s+(?:or|and)\s+(?:windows|gaps|holes|openings))*\b"
            r"(?:\s+(?:in|anywhere\s+in)\s+(?:it|them|its\s+\w+|the\s+\w+))?",
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
            r"\b(?:i\s+)?(?:do\s+not|dont|never)\s+(?:want|need|build|make|put|place|lay|"
            r"use)\s+(?:a|an|the|any)?\s*(?:"
            + _SHAPE_ALT
            + r")\b(?!\s+(?:taller|higher|shorter|longer|wider|bigger|smaller|larger|more|any|"
            r"too|so|than|over|under|above|below|exceed|of\b|on\b|in\b|at\b|to\s+the\b|near\b|"
            r"next\b|beside\b|behind\b|by\b))"
            r"\s*[,;:.]*\s*(?:(?:i\s+)?(?:want|need|would\s+like)\s+)?"
            r"(?:just\s+|only\s+|but\s+|instead\s*,?\s*)?",
            re.IGNORECASE,
        ),
        " ",
        "left out what is not wanted: '{0}'",
    ),
    # "… build a row of 3 instead": what remains once the unwanted structure is left out
    (re.compile(r"\s*,?\s*\b(?:instead|rather)\s*(?=[.!;]|$)", re.IGNORECASE), " ", ""),
    # "two pillars, but don't put anything across them": nothing is added there
    (
        re.compile(
            r",?\s*\b(?:but\s+|and\s+)?(?:do\s+not|dont|never)\s+(?:put|place|add|build|lay|"
            r"set|stack)\s+(?:anything|a\s+\w+|any\s+\w+)\s+(?:across|on\s+top\s+of|on\s+top|"
            r"onto|on|over|between|above)\s*(?:of\s+)?(?:them|it|both|the\s+\w+|each\s+\w+)?"
            r"(?!\s*(?:'s|\w))",
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
            r"\b(?:each|both|every)\s+(?:arm|leg|side|wing|branch)s?\s+(?:is\s+|are\s+)?"
            r"(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b"
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
            # "stack six cubes into two towers": the verb is the split's, not a stack of its own
            r"(?:\b(?:stack|split|divide|arrange|sort|pile|share|distribute|separate|group)\s+"
            r"(?:up\s+)?(?:the\s+)?)?"
            r"\b(?P<total>\d+|[a-z]+)\s+(?:cubes?|parts?|blocks?)\s+(?:as|in|into|making|to\s+make|"
            r"for|to\s+build|to\s+form)\s+"
            r"(?P<count>two|three|four|five|six|\d+)\s+(?:equal\s+|identical\s+|even\s+)?"
            r"(?P<noun>towers|stacks|columns|piles|rows|walls)"
            r"(?:\s+of\s+(?:equal|the\s+same)\s+(?:height|size|length))?",
            re.IGNORECASE,
        ),
        "{split}",
        "",
    ),
    (  # "two equal towers out of 8 cubes": four each
        re.compile(
            r"\b(?P<count>two|three|four|five|six|\d+)\s+(?:equal\s+|identical\s+|even\s+)?"
            r"(?P<noun>towers|stacks|columns|piles|rows|walls)"
            # "two towers of equal height using 8 cubes"
            r"(?:\s+(?:of\s+(?:equal|the\s+same)\s+(?:height|size|length)|(?:that\s+are\s+)?"
            r"(?:all\s+)?(?:the\s+same\s+height|equal(?:\s+in\s+height)?)),?)?"
            r"(?:\s+of(?=\s*,))?(?:\s*,)*"  # what a claim taken out ("of equal height") leaves
            r"\s+(?:out\s+of|from|using|made\s+(?:out\s+)?of|built\s+(?:out\s+of|from|with)|"
            # "two equal towers that together use 10 cubes"
            r"(?:(?:that|which)\s+)?(?:together|between\s+them|in\s+total|combined)\s+(?:use|take|"
            r"need|have|contain|make\s+up|total|come\s+to)s?)\s+"
            r"(?P<total>\d+|[a-z]+)\s+(?:cubes?|parts?|blocks?)\b(?!\s+(?:each|apiece))",
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
            r"(?:near|close\s+to|next\s+to)\s+(?:the\s+)?robot\b"
            # "not too close to the robot", "well away from the robot", "far from the robot"
            r"|\b(?:not|never)\s+(?:too\s+|so\s+|that\s+|very\s+|right\s+)?(?:near|close)(?:\s+to)?\s+"
            r"(?:the\s+)?robot\b|\b(?:well\s+away|far(?:\s+away)?)\s+from\s+(?:the\s+)?robot\b",
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
    # "4 separate single cubes in a line": each cube on its own, a part's width apart
    (
        re.compile(
            r"\b(\d+|two|three|four|five|six|seven|eight|nine|ten)\s+(?:separate|individual|"
            r"loose)\s+(?:single\s+)?(cubes|blocks)\b(?!\s*,?\s*(?:spread|spaced|\d))"
            r"(?!\s+(?:in|at|on|into)\s+(?:each|every|all|the\s+four|the\s+4)\b)"
            r"(?![^.;]*\b(?:\d+|one|two|three|a)\s+(?:cubes?|cm|mm|blocks?|parts?)\s+(?:apart|gaps?)\b)",
            re.IGNORECASE,
        ),
        " {0} {1} spaced 5 cm apart ",
        "read '{0}' as each standing alone, a part's width apart",
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
            # "on the right at the back": a side, not "exactly"
            r"(?<!\bthe\s)(?<!\bits\s)(?<!\btheir\s)(?<!\bfar\s)"
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
    # "a pen that has a 3 by 3 floor": an enclosure's floor is its inside
    (
        re.compile(
            r"\b(" + _ENCLOSURES + r")\s+(?:with|(?:that|which)\s+has|having)\s+(?:a|an)\s+"
            r"(\d+\s*(?:x|by)\s*\d+)\s+(?:floor|courtyard|yard)\b",
            re.I,
        ),
        " {0} with a {1} space inside ",
        "read '{0}' as the size of the inside",
    ),
    (
        re.compile(
            r"\b(?:with|(?:that|which)\s+has|having)\s+(?:a|an)\s+(\d+\s*(?:x|by)\s*\d+|\d+)\s+"
            r"(?:bottom|footprint|foot|floor)\b",
            re.I,
        ),
        " with a {0} base ",
        "",
    ),
    (_NOT_TOUCHING, "{not_touching}", "read '{0}' as a part's width apart"),
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
    (  # "a 4x4 square with a hole in the middle": hollow
        re.compile(
            r"\b(?:with|w)\s+(?:a|an|one)\s+(?:\w+\s+)?(?:hole|opening|void|gap|empty\s+space)\s+"
            r"(?:in\s+(?:the\s+)?(?:middle|centre|center)|inside|in\s+it)(?:\s+of\s+it)?",
            re.IGNORECASE,
        ),
        " hollow ",
        "read '{0}' as hollow",
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
    (  # "a tower on top left corner", "on its back right corner": a corner, which one not chosen
        re.compile(
            r"\bon\s+(?:top\s+of\s+)?(?:the\s+|its\s+(?=(?:left|right|front|back|rear)[\s-]*(?:hand\s+)?"
            r"corner))?(?:top\s+)?((?:front|back|rear)[\s-]+(?:left|right)|"
            r"(?:left|right|front|back|rear)(?:[\s-]+hand)?)\s+corner\b"
            r"(?!\s+of\s+the\s+(?:table|workspace|cell|bench)\b)(?:\s+of\s+(?:it|the\s+\w+))?",
            re.IGNORECASE,
        ),
        "{corner_named}",
        "",
    ),
    (  # "two towers of four, one either side of a block": a tower on each side of it
        re.compile(
            r"\b(?:two|2)\s+((?:[\w-]+\s+){0,2}?)(" + _SHAPE_ALT + r")s\b((?:\s+(?:of|with)\s+"
            r"[\w\s-]+?)?)\s*,?\s*one\s+(?:on\s+|at\s+)?(?:either|each)\s+(?:side|end)\s+of\b",
            re.IGNORECASE,
        ),
        " a {0}{1}{2} on either side of ",
        "read '{0}' as one on each side of it",
    ),
    (
        re.compile(
            r"\b(?:stacked\s+|resting\s+|standing\s+|sitting\s+)?(?:on|at|in(?=\s+(?:each|every|one|all|its|"
            r"their)\b[^,.;]{0,20}?\bcorners?\b(?!\s+of\s+the\s+(?:table|workspace|cell|work\s*area|area)\b)))"
            r"\s+(?:top\s+of\s+)?(?:(?:each|both|"
            r"either|one|every)\s+(?:of\s+(?:its|the)\s+)?(?:four\s+|4\s+|two\s+|2\s+)?"
            r"(?:ends|end|sides|side|corners|corner)"
            r"|(?:all\s+)?(?:its|their)\s+(?:four\s+|4\s+|two\s+|2\s+)?(?:corners|ends)"
            r"|all\s+(?:four|4)\s+(?:sides|corners)"
            r"|(?:all\s+)?the\s+(?:four\s+|4\s+|two\s+|2\s+)?(?:corners|ends)"
            r"(?=\s+of\s+(?:it|them|the)\b))"
            r"(?:\s+of\s+(it|them|the\s+\w+|an?\b))?",
            re.IGNORECASE,
        ),
        "{placement}",
        "",
    ),
    (  # "@ (0.50, 0.30, 0.70)": a position with a height above the table
        re.compile(
            r"\(\s*(-?\d+(?:\.\d+)?)\s*,\s*(-?\d+(?:\.\d+)?)\s*,\s*(-?\d+(?:\.\d+)?)\s*\)",
            re.IGNORECASE,
        ),
        "{xyz}",
        "",
    ),
    (  # "put a bridge thing across the top": a beam
        re.compile(
            r"\b(?:a|the|some)\s+(?:bridge|roof|lintel)\s+(?:thing|piece|bit|part)\b"
            r"(?=\s+(?:across|over|on\s+top|on\s+them))",
            re.IGNORECASE,
        ),
        " a beam ",
        "read '{0}' as a beam",
    ),
    (  # "two towers of 3 and put a beam across": the beam, joining them
        re.compile(
            r"\b(?:put|place|lay|add|set|stick|pop)\s+(?=(?:a|an|one|the)\s+(?:long\s+|single\s+)?"
            r"(?:beam|plank|lintel|girder)\s+(?:across|over|on\s+top|on\s+them|spanning))",
            re.IGNORECASE,
        ),
        " ",
        "",
    ),
    (  # "a tower right behind the middle of it": behind it, centred on it
        re.compile(
            r"\b(behind|in\s+front\s+of|to\s+the\s+(?:left|right)\s+of|next\s+to|beside|against)\s+"
            r"the\s+(?:middle|centre|center)\s+of\s+(it|them|the\s+\w+)",
            re.IGNORECASE,
        ),
        " {0} {1} ",
        "",
    ),
    (  # "the whole thing in the middle of the bench": the work surface's centre
        re.compile(
            r"\b(?:in|at)\s+the\s+(?:very\s+)?(?:middle|centre|center)\s+of\s+the\s+"
            r"(?:bench|table|workspace|work\s*space|work\s+area|cell|work\s+table|site)\b",
            re.IGNORECASE,
        ),
        " in the centre ",
        "",
    ),
    (  # "at table centre", "along the bench's front edge": the work surface's region, no table
        re.compile(
            r"\b(at|in|on|to|by|near|along|toward|towards)\s+(?:the\s+)?(?:work\s*)?"
            r"(?:table|bench|workspace|cell)(?:'s|s')?\s+(?=(?:centre|center|middle|front|back|"
            r"rear|left|right|edge|corner)s?\b)",
            re.IGNORECASE,
        ),
        " {0} the ",
        "",
    ),
    (  # "in the very centre of the plinth area": a part of the table with a name SDI does not
        # know (a plinth was built there, silently)
        re.compile(
            r"\b(of|in|at|on|to|near|by|within)\s+the\s+(?:" + _SHAPE_ALT
            + r")\s+(?:area|zone|region|spot|space)\b",
            re.IGNORECASE,
        ),
        " {0} the table ",
        "read '{0}' as on the work table: SDI knows no area of that name",
    ),
    (  # "a cube standing in the gap of the U", "in its opening": no place SDI has
        re.compile(
            r"\b(?:standing\s+|placed\s+|set\s+)?(?:in|inside|within|into)\s+(?:the|its)\s+(?:gap|opening|"
            r"mouth|hollow)\b(?:\s+of\s+(?:the\s+u(?:[\s-]*shape)?|it))?",
            re.IGNORECASE,
        ),
        "{in_the_u}",
        "",
    ),
    (  # "put two more on top of that one": that one is it
        re.compile(
            r"(?<=\b(?:of|on|to|by|at)\s)(?:that|this)\s+one\b(?!\s+(?:of|with|high|tall|long)\b)",
            re.IGNORECASE,
        ),
        "it",
        "",
    ),
    (  # "and erect upon its central cube a column of three": on top of it, centred
        re.compile(
            r"\b(?:up)?on\s+(?:(?:the\s+)?top\s+of\s+)?its\s+(?:central|centre|center|middle)\s+(?:cube|part|block|"
            r"cell|position|square|brick)\b",
            re.IGNORECASE,
        ),
        " on top of it ",
        "read '{0}' as on top of it, centred",
    ),
    (  # "a wall with a tower of 2 on top of its left end": on top, at that end
        re.compile(
            r",?\s*\b(?:standing|sitting|resting|placed|set|stood|stacked)?\s*on\s+(?:(?:the\s+)?top\s+of\s+"
            r"(?:the\s+(?:cube|one|block|part)\s+(?:at|on)\s+)?(?:its|the)|its)\s+(left|right|front|back|rear)"
            r"(?:[\s-]+hand)?\s+end(?:\s+of\s+(?:it|the\s+(?!table|workspace|bench|cell)\w+))?\b"
            r"(?!\s+of\s+the\s+(?:table|workspace|bench|cell))",
            re.IGNORECASE,
        ),
        "{top_end}",
        "",
    ),
    (  # "with a 2-storey column standing on its rear left corner": on top, at that corner
        re.compile(
            r",?\s*\b(?:standing|sitting|resting|placed|set|stood|mounted|stacked)?\s*(?:up)?on\s+(?:its|the)\s+"
            r"(back|rear|front)[\s-]+(left|right)(?:[\s-]+hand)?\s+(?:corner|cube|block|brick|cell)"
            r"(?:\s+of\s+(?:it|the\s+\w+))?\b",  # "on its back-left cube": the corner one
            re.IGNORECASE,
        ),
        "{top_corner}",
        "",
    ),
    (  # "a column rising from its centre": on top of it, centred
        re.compile(
            r"\b(?:rising|growing|sticking\s+up|coming\s+up|going\s+up)\s+(?:up\s+)?(?:from|out\s+of)\s+"
            r"(?:its|the)\s+(?:centre|center|middle)(?:\s+of\s+(it|them|the\s+\w+))?",
            re.IGNORECASE,
        ),
        " on top of it ",
        "read '{0}' as on top of it, centred",
    ),
    (
        re.compile(
            r"\b(\d+|one|two|three|four|five)\s+(?:(" + _COUNTED + r")\s+)?(more|less|fewer)\s+"
            r"(?:cubes?\s+|parts?\s+|(" + _COUNTED + r")\s+)?than\s+(\d+|[a-z]+)\b",
            re.IGNORECASE,
        ),
        "{arith}",
        "",
    ),
    (
        re.compile(
            r"\b(\d+(?:\.\d+)?)\s*(cm|mm|m)\s+(?:to\s+(?:the\s+)?|towards\s+the\s+)?"
            r"(left|right|back|front|in\s+front|behind|forward)(?:\s+(?:of|from))?\s+(?:the\s+)?"
            r"(?:centre|center|middle)(?:\s+of\s+the\s+(?:table|workspace|cell|area))?",
            re.IGNORECASE,
        ),
        "{from_centre}",
        "",
    ),
    (
        re.compile(
            r"(?<=\bof\s)(\d+|one|two|three|four|five)\s+(more|fewer|less)\b(?!\s+than)"
            r"(?:\s+(?:cubes?|parts?))?",
            re.IGNORECASE,
        ),
        "{relative}",
        "",
    ),
    (
        re.compile(
            r"\b(\d+|[a-z]+)\s+(plus|minus|times|multiplied\s+by)\s+(\d+|[a-z]+)\b",
            re.IGNORECASE,
        ),
        "{operation}",
        "",
    ),
    (  # "a tower with minus 3 cubes": a negative count, refused as one
        re.compile(r"\b(?:minus|negative)\s+(\d+)\s*(?:cubes?|parts?|levels?|steps?)?", re.I),
        "{negative}",
        "",
    ),
    (  # "with the tallest one in the middle": the order of several structures
        re.compile(
            r",?\s*(?:and\s+|with\s+)?(?:the\s+)?(?<!\ba\s)(?<!\ban\s)(?<!\banother\s)"
            r"(tallest|highest|biggest|largest|longest|shortest|"
            r"lowest|smallest|taller|higher|bigger|larger|longer|shorter|lower|smaller)\s+"
            r"(?:one|tower|stack|column|pillar|wall|row)?\s*(?:(?:goes|is|stands|sits|should\s+(?:be|go|"
            r"stand)|(?:has|needs|wants)\s+to\s+(?:be|go|stand)|must\s+(?:be|go|stand))\s+)?"
            r"(?:in\s+the\s+(?:middle|centre|center)|(?:on|at|to)\s+the\s+"
            r"(left|right|front|back)|(behind|in\s+front))\b",
            re.IGNORECASE,
        ),
        "{extreme_at}",
        "",
    ),
    (  # "a 2 by 2 block, a tower of six and another block, the tower in the middle": the one
        # named once stands in the middle of the line (not a second tower at the table's centre)
        re.compile(
            r"(?:,\s*(?:and\s+|with\s+)?|\s+(?:and|with)\s+)the\s+"
            r"(?:(?P<a>" + _MIDDLE_ONES + r")\s+"
            r"(?:(?:goes|is|stands|sits)\s+)?in\s+the\s+(?:middle|centre|center)\b(?!\s+of\b)|"
            r"(?:middle|centre|center)\s+(?P<b>" + _MIDDLE_ONES + r")\b(?=\s*(?:[.;!?]|$)))",
            re.IGNORECASE,
        ),
        "{named_in_middle}",
        "",
    ),
    (  # "with 9 cubes on the bottom", "16 blocks in the bottom layer": the bottom level's count
        re.compile(
            r"\b(?:with\s+|having\s+)?(\d+|[a-z]+)\s+(?:cubes?|blocks?|bricks?|parts?)\s+(?:on|in|at|"
            r"along|across)\s+(?:the\s+)?(?:very\s+)?(?:bottom|base|ground)(?:\s+(?:row|layer|level|"
            r"tier|course))?\b",
            re.IGNORECASE,
        ),
        "{bottom_count}",
        "",
    ),
    (  # "pyramid. 4 levels. base 4 by 4.": a base said on its own after a pyramid is its base
        re.compile(
            r"([.;!?\n]\s*)(?:its\s+|the\s+)?(base\s*(?:is\s+|of\s+|:\s*|=\s*)?\d)",
            re.IGNORECASE,
        ),
        "{base_of}",
        "",
    ),
    (  # "pyramid, base 25cm", "Pyramid, 3 tiers, base 9 pcs": a pyramid's base said bare
        re.compile(
            r"(?<![\w-])base\s*(?:of\s+|:\s*|=\s*|is\s+)?(\d+(?:\.\d+)?)\s*(cm|mm|m|cubes?|"
            r"blocks?|bricks?|parts?|pieces?|pcs)?\b(?:\s+square\b)?"
            r"(?!\s*(?:x|by|wide|long|deep|across|side)\b)",
            re.IGNORECASE,
        ),
        "{pyramid_base}",
        "",
    ),
    (  # "a pyramid with a 15cm base": a square base that wide (of a pyramid only)
        re.compile(
            r"(?<=\bpyramid\s)(?:with|w/)\s+an?\s+(\d+(?:\.\d+)?\s*(?:cm|mm|m))\s+(?:square\s+)?base\b",
            re.IGNORECASE,
        ),
        " with a {0} by {0} base ",
        "read '{0}' as a square base",
    ),
    (  # "a 35 cm base side", "base sides of 4": a square base
        re.compile(
            r"\b(\d+(?:\.\d+)?\s*(?:cm|mm|m)|\d+(?:[- ]cubes?)?)\s+(?:square\s+)?base\s+sides?\b"
            r"|\bbase\s+sides?\s+(?:of\s+|is\s+|are\s+)?(\d+(?:\.\d+)?\s*(?:cm|mm|m)|\d+)\b",
            re.IGNORECASE,
        ),
        "{square_base}",
        "",
    ),
    (  # "space between every one of them": the structures stand apart (as they do anyway)
        re.compile(
            r"\b(?:with\s+)?(?:some\s+|a\s+bit\s+of\s+)?(?:space|room|a\s+gap|gaps)\s+between\s+"
            r"(?:every\s+one\s+of\s+them|each\s+of\s+them|all\s+of\s+them|them|each(?:\s+one)?)\b",
            re.IGNORECASE,
        ),
        " ",
        "read '{0}' as standing apart (separate structures always do)",
    ),
    (  # "with no cube missing", "no gaps": solid, which every structure is
        re.compile(
            r",?\s*\b(?:with\s+)?(?:no|none\s+of\s+the)\s+(?:cubes?|parts?|blocks?)\s+(?:missing|left\s+out)\b"
            r"|,?\s*\bwith\s+no\s+(?:gaps|holes)\b",
            re.IGNORECASE,
        ),
        " ",
        "'{0}': built solid",
    ),
    (  # "keep it under six bricks tall", "fewer than 5 steps": the most below the bound
        re.compile(
            r"(?:,\s*)?\b(?:but\s+|and\s+)?(?:keep(?:ing)?\s+(?:it|them|the\s+\w+)\s+|"
            r"(?:that\s+|which\s+)?(?:stays?|is|are|remains?)\s+)?"
            r"(?:under|below|beneath|less\s+than|fewer\s+than|lower\s+than|shorter\s+than)\s+"
            r"(\d+|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)\s*"
            r"(cubes?|bricks?|blocks?|parts?|cm|mm|centimet(?:re|er)s)?\s*"
            r"(tall|high|in\s+height|levels?|layers?|steps?|floors?|tiers?|storeys?)\b",
            re.IGNORECASE,
        ),
        "{below}",
        "",
    ),
    (  # "don't make the pillars taller than 2": at most 2, built 2
        re.compile(
            r",?\s*\b(?:but\s+)?(?:do\s+not|never)\s+(?:make|build|let)\s+(it|them|the\s+\w+)\s+"
            r"(?:any\s+)?(?:taller|higher)\s+than\s+(\d+|one|two|three|four|five|six)\b",
            re.IGNORECASE,
        ),
        "{at_most}",
        "",
    ),
    (  # "two towers in the same spot", "on top of itself", "a tall short tower": impossible
        re.compile(
            r"\b(?:in|at|on)\s+(?:exactly\s+|precisely\s+)?the\s+(?:very\s+)?same\s+(?:spot|place|"
            r"position|location)\b(?!\s+as\b)|\b(?:on\s+(?:top\s+of\s+)?|in(?:side)?\s+|around\s+)itself\b|"
            r"\b(?:tall|high)\s+(?:and\s+)?(?:short|low)\b|\b(?:short|low)\s+(?:and\s+)?(?:tall|high)\b|"
            r"\b(?:big|large)\s+(?:and\s+)?(?:small|little|tiny)\b|\b(?:small|little|tiny)\s+(?:and\s+)?"
            r"(?:big|large)\b",
            re.IGNORECASE,
        ),
        "{impossible}",
        "",
    ),
    (  # "put a tower um over there", "right here": a place pointed at
        re.compile(
            r"\b(?:(?:somewhere\s+)?over\s+(?:there|here|yonder)|right\s+(?:there|here)|just\s+(?:there|here)|"
            r"(?:put|place|set|build)\s+(?:it|that|one)\s+(?:there|here))\b(?!\s*(?:is|are|was|were)\b)",
            re.IGNORECASE,
        ),
        "{pointed}",
        "",
    ),
    (  # "a staircase going down into the table", "floating above the table": not buildable
        re.compile(
            r"\b(?:going\s+|sunk\s+|dug\s+|reaching\s+)?(?:down\s+)?(?:into|under|below|beneath|through)\s+"
            r"the\s+(?:table|floor|surface|ground)(?:\s+surface)?\b|"
            r"\b(?:outside|off|beyond|past)\s+(?:of\s+)?the\s+(?:table|workspace|cell|bench)(?:'s\s+edge)?\b|"
            # "on the floor next to the table": off the table
            r"\bon\s+the\s+(?:floor|ground)\s+(?:next\s+to|beside|by|near|in\s+front\s+of|behind)\s+"
            r"the\s+(?:table|bench|cell)\b|"
            r"\b(?:floating|hovering|hanging|"
            r"suspended)\b(?:\s+(?:\d+(?:\.\d+)?\s*(?:cm|mm|m)\s+)?(?:above|over|off)\s+the\s+"
            r"(?:table|floor|surface|ground))?|\bin\s+(?:mid-?\s*air|the\s+air)\b",
            re.IGNORECASE,
        ),
        "{unsupported}",
        "",
    ),
    (  # "2 tower 3 high": a count before a singular noun whose size is said after it
        re.compile(
            r"(?<!x\s)(?<!by\s)\b([2-9]|two|three|four|five|six)\s+" + _COUNTED_NOUN, re.IGNORECASE
        ),
        " {0} {1}s ",
        "read '{0}' as a count of structures",
    ),
    (
        re.compile(r"\b(?:1|one)\s+" + _COUNTED_NOUN, re.IGNORECASE),
        " a {0} ",
        "",
    ),
    (  # "a tower of 3 and 2 more towers", "and three more like it": copies of the one before
        re.compile(
            r"\s*,?\s*\b(?:and\s+|plus\s+|then\s+)?(\d+|two|three|four|five|six)\s+more\s+(?:("
            + _STRUCTURE_ALT
            + r")|(?:of\s+(?:them|those|these)|(?:just\s+|exactly\s+)?like\s+(?:it|that|this|the\s+"
            r"first)))\b"
            # "…, one to its left and one to its right": where the two copies stand
            r"(?:\s*,?\s*one\s+(" + _ITS_SIDE + r")\s*,?\s*and\s+(?:one|the\s+other|another\s+"
            r"[a-z]+)\s+(" + _ITS_SIDE + r"))?",
            re.IGNORECASE,
        ),
        "{more_of}",
        "",
    ),
    (  # "a podium 2 by 2, 2 high", "a 3x3 podium": a podium given a footprint is a raised block
        re.compile(
            r"\bpodium(\s*,?\s*(?:\d+|one|two|three|four|five|six)\s*(?:x|by)\s*"
            r"(?:\d+|one|two|three|four|five|six)\b)"
            r"|(\b(?:\d+|one|two|three|four|five|six)\s*(?:x|by)\s*(?:\d+|one|two|three|four|five|"
            r"six)\s+)podium\b",
            re.IGNORECASE,
        ),
        "{1}block{0}",
        "read '{0}' as a raised block (a podium of that footprint)",
    ),
    (  # "a row of cubes, not a tower, five of them": the row's count, not five rows
        re.compile(
            r"\b(rows?|lines?|stacks?|towers?|columns?|piles?)\s+of\s+(?:cubes|blocks)\b"
            r"([^.;:!?\d]*?),?\s*\b(two|three|four|five|six|seven|eight|nine|ten|\d+)\s+of\s+"
            r"(?:them|those|these)\b\s*(?=$|[,.;!])",
            re.IGNORECASE,
        ),
        "{0} of {2}{1} ",
        "read '{0}' as the count of cubes in it",
    ),
    (  # "a tower of 4 with a smaller one next to it, 2 high": the comparison the sizes make
        re.compile(
            r"\b(?:an?|one)\s+(smaller|shorter|lower|littler|little|small|taller|higher|bigger|larger)"
            r"\s+(one|tower|stack|column|pillar)\b(?=[^.;]*?\b(\d+)\s+(?:cubes?\s+)?(?:high|tall)\b)",
            re.IGNORECASE,
        ),
        "{compared_one}",
        "",
    ),
    (  # "ring 4x4, 2 of them": that many of the one described
        re.compile(
            r",?\s*\b(two|three|four|five|[2-5])\s+of\s+(?:them|those|these|it)\b\s*(?=$|[,.;!])",
            re.IGNORECASE,
        ),
        "{copies_of}",
        "",
    ),
    (  # "the base is 25 cm each side", "base 4 a side": a square base
        re.compile(
            r"\bbase\s+(?:is\s+|of\s+)?(\d+(?:\.\d+)?\s*(?:cm|mm|m)|\d+)\s+(?:on\s+)?(?:each|every|a|per)\s+"
            r"side\b",
            re.IGNORECASE,
        ),
        " {0} by {0} base ",
        "read '{0}' as a square base",
    ),
    (  # "a perimeter fence", "a boundary wall": a ring (not one "running along the left side")
        re.compile(r"\b(?:perimeter|boundary)\s+(?:fence|wall)\b(?![^.;]*\b(?:along|running|runs)\b)",
                   re.IGNORECASE),
        " enclosure ",
        "read '{0}' as a ring",
    ),
    (  # "something a toy car could drive under": a bridge
        re.compile(
            r"\b(?:something|a\s+thing|a\s+structure|one)\s+(?:that\s+)?(?:a|an|my|the)\s+(?:\w+\s+){0,3}?"
            r"(?:could|can|might|will)\s+(?:walk|drive|pass|go|fit|crawl|roll|ride|sail|run)\s+"
            r"(?:under|underneath|beneath|through)\b",
            re.IGNORECASE,
        ),
        " a bridge ",
        "read '{0}' as a bridge (something to pass under)",
    ),
    (  # "a slab. then a second layer, same size. then a third": each layer on the one before
        re.compile(
            r"\b((?:a\s+(?:second|third|fourth|fifth|new|next)|another)\s+(?:layer|level|tier|course))"
            r"\b(?![^.;]*\b(?:on|onto|atop|above|over|beside|next|behind|left|right|front|under)\b)"
            r"(?:\s*,\s*(\d+\s*(?:x|by)\s*\d+)\s*(?=,))?"
            r"|(?<=\bthen\s)(a\s+(?:third|fourth|fifth))(?=\s*(?:[.;!]|$))",
            re.IGNORECASE,
        ),
        "{layer_on_top}",
        "",
    ),
    (  # "a beam across the two", "from one tower across to the other one": across them
        re.compile(
            r"\b(?:(across|over|on\s+top\s+of|between)\s+the\s+two|from\s+(?:the\s+)?(?:one|first)"
            r"(?:\s+[a-z]+)?\s+(?:across\s+)?to\s+the\s+(?:other|second)(?:\s+one)?)"
            r"(?=\s*(?:$|[,.;!?]|and\b|then\b|with\b|just\b))",
            re.IGNORECASE,
        ),
        "{across_them}",
        "",
    ),
    (  # "a long beam": the cell's one beam (3 cubes long)
        re.compile(r"\b(?:long|longer|big|large|flat)\s+(?=(?:beam|plank|lintel)\b)", re.I),
        "",
        "",
    ),
    (  # "pillars with something across them": a beam
        re.compile(
            r"\b(?:something|a\s+piece|a\s+part|a\s+long\s+piece)\s+(?=(?:across|over|on\s+top\s+of)\s+"
            r"(?:them|both|the\s+two)\b)",
            re.IGNORECASE,
        ),
        " a beam ",
        "read '{0}' as a beam",
    ),
    (  # "cubes six, in one column": a count after its noun
        re.compile(
            r"\b(cubes|blocks|bricks|towers|stacks|rows|walls)\s+(two|three|four|five|six|seven|eight|nine|ten|"
            r"\d+)\b(?!\.\d)(?=\s*(?:$|[,.;]))",
            re.IGNORECASE,
        ),
        " {1} {0} ",
        "",
    ),
    (  # "each of cubes 5": each of 5 cubes
        re.compile(
            r"\bof\s+(cubes|blocks|bricks)\s+(\d+)\b(?!\.\d)(?!\s*(?:by|x|cm|mm|m|dm|in|inch|inches|ft|feet|"
            r"tall|high|long|wide|deep|thick)\b)",
            re.IGNORECASE,
        ),
        " of {1} {0} ",
        "",
    ),
    (  # "not left to right, front to back": the axis said second
        re.compile(
            r"\bnot\s+(?:running\s+|going\s+)?(?:left\s+to\s+right|right\s+to\s+left|side\s+to\s+side)\b"
            r"\s*[,;:]?\s*(?:but\s+)?(?:front\s+to\s+back|back\s+to\s+front)?",
            re.IGNORECASE,
        ),
        " running front to back ",
        "read '{0}' as running front to back",
    ),
    (
        re.compile(
            r"\bnot\s+(?:running\s+|going\s+)?(?:front\s+to\s+back|back\s+to\s+front)\b"
            r"\s*[,;:]?\s*(?:but\s+)?(?:left\s+to\s+right|right\s+to\s+left|side\s+to\s+side)?",
            re.IGNORECASE,
        ),
        " running left to right ",
        "read '{0}' as running left to right",
    ),
    (  # "a tower at its low end", "at the foot of the stairs", "touching its high end": beside
        # that end of a staircase ("at its top end", "at the top of the stairs" are left as they
        # were: a tower there may stand on the top step)
        re.compile(
            r"\b(?:at|by|beside|next\s+to|against|touching|near(?:\s+to)?|close\s+to)\s+(?:its|the)"
            r"\s+(?:(?:low|lower|lowest|bottom|high|higher|highest|upper|tall|taller)\s+end|foot"
            r"|bottom(?=\s+of\s+(?:it|the\s+st))|(?:top|highest|upper|tallest|lowest|bottom)\s+"
            r"(?:step|stair|tread))\b"
            r"(?:\s+of\s+(?:it|the\s+(?:staircase|stairs|steps|stair)))?"
            r"|\s*,\s*(?:at\s+)?(?:its\s+|the\s+)?(?:low|lower|bottom)\s+end\b",
            re.IGNORECASE,
        ),
        "{stair_end}",
        "",
    ),
    (  # "then add a second beam on top of the first": one beam a span
        re.compile(
            r"\b(?:(?:add|put|place|lay|stack|set)\s+)?(?:a\s+second|another|one\s+more|an\s+extra|a\s+2nd)"
            r"\s+(?:beam|plank|lintel|girder)\s+(?:on\s+top(?:\s+of\s+(?:the\s+first(?:\s+one)?|it|that|"
            r"the\s+(?:other|beam)))?|on\s+(?:it|that)|above\s+(?:it|that))",
            re.IGNORECASE,
        ),
        "{beam_on_beam}",
        "",
    ),
    (  # "on top of the robot", "on the conveyor": nothing is built on the cell's machines
        re.compile(
            r"\b(?:on\s+top\s+of|on|onto|atop|above|in|into|inside)\s+(?:the\s+|my\s+|your\s+)?"
            r"(?:robots?|arms?|grippers?|conveyors?|operators?|camera|controller|cabinet|fence\s+door|"
            r"me|you|him|her|hand|head)\b",
            re.IGNORECASE,
        ),
        "{unsupported}",
        "",
    ),
    (  # "a bridge, but without the beam": its two pillars
        re.compile(
            r"\ban?\s+(?:bridge|gate|arch)\b[^.;]*?\bwithout\s+(?:the\s+|its\s+|a\s+)?(?:beam|lintel|top|deck)s?\b"
            r"(?:\s+this\s+time)?(?:\s*[,;:—–-]*\s*(?:just|only)?\s*(?:its|the)\s+two\s+(?:pillars|posts|towers|legs)"
            r"((?:\s+of\s+\w+)?))?",
            re.IGNORECASE,
        ),
        " two towers{0} ",
        "read '{0}' as the two pillars alone",
    ),
    (  # "a row of 5 that is also a tower of 5": a contradiction, refused
        re.compile(
            r"\b(" + _SHAPE_ALT + r")\b[^,.;]{0,30}?\b(?:that|which|and)\s+(?:is|'s)\s+(?:also|"
            r"at\s+the\s+same\s+time|simultaneously)\s+an?\s+(" + _SHAPE_ALT + r")\b",
            re.IGNORECASE,
        ),
        "{also_a}",
        "",
    ),
    (  # "…, then one of 3, all in a row with gaps": how separate structures stand anyway
        re.compile(
            r",?\s*\b(?<!\bnot\s)(?<!\bnever\s)(?:all(?:\s+(?:two|three|four|five|six|\d))?|them\s+all|all\s+of\s+them|each)\s+"
            r"(?:in\s+(?:a|one)\s+(?:straight\s+)?(?:row|line)|side\s+by\s+side)"
            r"(?:\s*,?\s*(?:with\s+(?:gaps?|space)(?:\s+between(?:\s+them)?)?|spaced\s+out|apart))?",
            re.IGNORECASE,
        ),
        " ",
        "read '{0}' as the structures side by side (separate structures stand apart)",
    ),
    (  # "three towers: two, four and six high": a list of heights, one per tower
        re.compile(
            r"(?<=[:,])\s*(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s*,\s*(\d+|one|two|"
            r"three|four|five|six|seven|eight|nine|ten)\s*,?\s+and\s+(\d+|one|two|three|four|five|six|"
            r"seven|eight|nine|ten)\s+(?:cubes?\s+)?(?:high|tall)\b",
            re.IGNORECASE,
        ),
        "{height_list}",
        "",
    ),
    (  # "three towers of 3 in a row with gaps": how separate structures stand anyway
        re.compile(
            r"(?:(?<=s)|(?<=high)|(?<=tall)|(?<=\d)|(?<=standing)|(?<=placed)|(?<=arranged)|"
            r"(?<=set)|(?<=spaced)|(?<=set\sout)|(?<=lined\sup)|(?<=s,)|(?<=high,)|(?<=tall,)|(?<=\d,)|(?<=\d\s,)|(?<=er)|(?<=er,)|"
            r"(?<=one)|(?<=two)|(?<=three)|(?<=four)|(?<=five)|(?<=six)|(?<=seven)|(?<=eight)|(?<=nine))\s+in\s+"
            r"(?:a|one|a\s+single)\s+"
            r"(?:straight\s+|neat\s+)?"
            r"(?:row|line)"
            r"(?:\s*,?\s*(?:with\s+(?:gaps?|space)(?:\s+between(?:\s+them)?)?|"
            r"spaced\s+out|apart))?\b(?=\s*(?:,|\.|;|then\b|and\b|$|(?:at|on|in|along)\s+the\s+(?:back|"
            r"front|left|right|middle|centre|center)\b|(?:running\s+|going\s+)?"
            r"(?:from\s+)?(?:the\s+)?(?:front|back|left|right)\s+to\s+(?:the\s+)?"
            r"(?:front|back|left|right)\b))",
            re.IGNORECASE,
        ),
        "{in_a_row}",
        "",
    ),
    (  # "a 6 by 2 slab, double thickness": two layers
        re.compile(r"\b(double|triple)[- ](?:thickness|thick|height|layered|layer|deep)\b", re.I),
        "{layers_word}",
        "",
    ),
    (  # "none of them the same height", "all different heights"
        re.compile(
            r",?\s*\b(?:with\s+|and\s+)?(?:(?:none\s+of\s+them|no\s+two(?:\s+of\s+them)?)\s+(?:are\s+|is\s+)?"
            r"(?:the\s+same|alike|equal)(?:\s+(?:height|size))?|(?:all|each)\s+(?:of\s+)?(?:a\s+)?"
            r"different\s+(?:heights?|sizes?)|(?:of\s+)?different\s+heights)\b",
            re.IGNORECASE,
        ),
        "{all_different}",
        "",
    ),
    (  # "three things, left to right: …": the order they are named in
        re.compile(r"\b(?:from\s+)?(left|right)\s+to\s+(right|left)\s*:", re.IGNORECASE),
        "{listing}",
        "",
    ),
    (  # "three towers of 1, 2 and 3, from left to right": the order too (the words stay: a
        # single structure runs that way)
        re.compile(
            r"(?<!running\s)(?<!going\s)(?<!oriented\s)(?<!aligned\s)(?<!facing\s)"
            r"\b(?:from\s+)?(?:the\s+)?(left|right|front|back)\s+to\s+(?:the\s+)?(right|left|back|front)\b",
            re.IGNORECASE,
        ),
        "{listing_said}",
        "",
    ),
    (  # "a 2 x 3 array of 2-high stacks": that many stacks, in an arrangement SDI does not make
        re.compile(
            r"\b(?:a\s+|an\s+)?(\d+)\s*(?:x|by)\s*(\d+)\s+(?:array|grid|rack|matrix|pattern|layout)\s+of\s+"
            r"(?:(\d+)[- ](?:high|tall|cube)\s+)?(stacks|towers|columns|pillars|posts)\b",
            re.IGNORECASE,
        ),
        "{array_of}",
        "",
    ),
    (  # "a tower that is 1 cube taller than the wall": the wall's height and one
        re.compile(
            r"\b(?:(?:that|which)\s+(?:is|are)\s+)?(?:(\d+|one|two|three|a)\s+(?:cubes?\s+|levels?\s+)?)?"
            r"(taller|higher|shorter|lower|longer)\s+than\s+(?:the|that|this)\s+"
            r"(tower|stack|column|pillar|wall|row|staircase|stairs|pyramid|block|slab|line)\b",
            re.IGNORECASE,
        ),
        "{than_named}",
        "",
    ),
    (  # "a tower (twice) as tall as the staircase": the size of the one named before
        re.compile(
            r"\b(?:(twice|double|thrice|half)\s+)?(?:exactly\s+|just\s+)?(?:as|so)\s+(tall|high|long|wide)"
            r"\s+as\s+(?:the|that|this)\s+"
            r"(tower|stack|column|pillar|wall|row|staircase|stairs|pyramid|block|slab|platform|line|grid|"
            r"square|pad)\b"
            r"(?:\s+(?:is|was|will\s+be)(?:\s+(tall|high|long|wide)\b)?)?",
            re.IGNORECASE,
        ),
        "{as_big_as}",
        "",
    ),
    (  # "a tower behind it, lined up with the middle of the row": beside it is centred on it
        re.compile(
            r",?\s*\b(?:(?:lined|lining)\s+up|aligned|centred|centered|in\s+line)\s+(?:with|on|to)\s+"
            r"(?:the\s+)?(?:middle|centre|center)\s+of\s+(?:it|that|the\s+\w+)(?=\s*(?:$|[,.;]|and\b))",
            re.IGNORECASE,
        ),
        "{centred_beside}",
        "",
    ),
    (  # "four towers of 2 in a 2 x 2 grid", "six stacks in two rows of three": rows by columns
        re.compile(
            r",?\s*\b(?:(?:arranged|set\s+out|laid\s+out|placed|standing|stood|set|positioned|"
            r"spaced)\s+)?(?:in|into|as)\s+(?:an?\s+)?(?:(\d|two|three|four)\s*(?:x|by|×)\s*(\d|two|"
            r"three|four)\s+(?:grid|array|square|block|pattern|matrix|layout|formation|arrangement)|"
            r"(two|three|four|[2-4])\s+rows\s+of\s+(two|three|four|[2-4])(?:\s+each)?)\b",
            re.IGNORECASE,
        ),
        "{grid_of}",
        "",
    ),
    (  # "four stacks of 2 arranged in a square": rows and columns where the count makes one
        re.compile(
            r",?\s*\b(?:(?:arranged|set\s+out|laid\s+out|placed|standing|stood|set|positioned)\s+in"
            r"|(?<=s)\s+in|(?<=\d)\s+in|(?<=high)\s+in|(?<=tall)\s+in|(?<=,)\s+in)\s+(?:a\s+)?"
            r"(square|circle|ring|triangle|cross|grid|diamond)(?:\s+(?:formation|pattern|arrangement|"
            r"shape|layout))?\b(?!\s+(?:of|with|\d)\b)",
            re.IGNORECASE,
        ),
        "{arrangement}",
        "",
    ),
    (  # "halfway between front and back": centred that way
        re.compile(
            r"\b(?:halfway|half\s+way|midway|mid\s+way)\s+(?:between|from)\s+(?:the\s+)?"
            r"(front|back|left|right)\s+(?:and|to)\s+(?:the\s+)?(?:front|back|left|right)\b"
            r"(?:\s+(?:edges?|sides?))?(?:\s+of\s+the\s+(?:table|workspace|cell))?",
            re.IGNORECASE,
        ),
        "{halfway}",
        "",
    ),
    (  # "centred left-right": across the table, the default; the other region word stays
        re.compile(
            r",?\s*\b(?:centred|centered|central)\s+(?:left[- ]to[- ]right|left[- ]right|"
            r"side[- ]to[- ]side|sideways|between\s+left\s+and\s+right)\b",
            re.IGNORECASE,
        ),
        " ",
        "read '{0}' as centred across the table (y)",
    ),
    (  # "3 across, 5 back": across the table is the width, back from the robot the depth
        re.compile(
            r"\b(\d+|"
            + _NUMBER_WORD
            + r")\s+across\s*,?\s*(?:and\s+)?(\d+|"
            + _NUMBER_WORD
            + r")\s+"
            r"(?:back|going\s+back|front\s+to\s+back|back\s+to\s+front)\b",
            re.IGNORECASE,
        ),
        " {0} wide , {1} deep ",
        "read '{0}' as wide and deep",
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
    (  # "along the left edge": running front to back, against it ("side": on that side)
        re.compile(
            r"\balong\s+(?:the\s+)?(left|right)(?:[\s-]hand)?\s+(?:edge|boundary|border)\b", re.I
        ),
        " along x at the {0} edge ",
        "read '{0}' as running front to back against that edge of the workspace",
    ),
    (
        re.compile(r"\balong\s+(?:the\s+)?(front|back)\s+(?:edge|boundary|border)\b", re.I),
        " along y at the {0} edge ",
        "read '{0}' as running left to right against that edge of the workspace",
    ),
    (
        re.compile(r"\balong\s+(?:the\s+)?(left|right)\s+side\b", re.IGNORECASE),
        " along x on the {0} ",
        "",
    ),
    (
        re.compile(r"\balong\s+(?:the\s+)?(front|back)\s+side\b", re.IGNORECASE),
        " along y at the {0} ",
        "",
    ),
    (
        re.compile(
            # "towers: 3" is three towers; "three stacks: 4 high" keeps its count
            r"(?<!\d\s)(?<!two\s)(?<!three\s)(?<!four\s)(?<!five\s)(?<!six\s)"
            r"\b(towers|rows|walls|stacks|columns|pyramids|pads)\s*[:=]\s*(\w+)\b(?!\s+(?:high|tall|long))",
            re.I,
        ),
        " {1} {0} ",
        "",
    ),
    (  # "width: 10cm / depth: 15cm / height: 5cm": a size with its unit and its side
        re.compile(
            r"\b(length|len|width|depth|height|thickness)\s*[:=]\s*(\d+(?:\.\d+)?\s*(?:cm|mm|m|in|inches|ft))\b",
            re.IGNORECASE,
        ),
        "{keyed_size}",
        "",
    ),
    (
        re.compile(
            r"\bheight(?:[_ ]?(?:cubes|in[_ ]cubes|parts|levels))?\s*[:=]\s*(\d+)\b"
            r"(?!\s*(?:cm|mm|m)\b)",
            re.IGNORECASE,
        ),
        " {0} high ",
        "",
    ),
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
    (  # "a wall made of 8 cubes, two rows of four": a wall's rows are its courses
        re.compile(
            r"\b(wall|fence|parapet)\b([^.;]{0,30}?)\b(\d+|two|three|four|five)\s+(?:rows|"
            r"courses|layers)\s+of\s+(\d+|two|three|four|five|six|seven|eight)\b(?!\s+(?:rows|walls))",
            re.IGNORECASE,
        ),
        " {0} {1} {2} levels of {3} ",
        "",
    ),
    (
        re.compile(
            r"\b(\d+|two|three|four|five)\s+rows\s+(?:with|of)\s+(\d+|[a-z]+)\s+(?:cubes?\s+)?"
            r"(?:in\s+each|each|apiece)\b",
            re.IGNORECASE,
        ),
        "{rows_of}",
        "",
    ),
    (  # "two towers of 3 and a beam across": the beam lies across the towers
        re.compile(
            r"\b(towers?|pillars?|columns?|stacks?|posts?|uprights?)\b([^.;]*?)\s*,?\s*\b(?:and|plus|with)\s+"
            r"(?:a|one|an)\s+(beam|plank|lintel|girder|bar|deck)\s+(?:across|over|on\s+them|"
            r"on\s+top|(?:resting|sitting|lying|laid)\s+(?:on|across)\s+(?:both|them|the\s+two|top))"
            r"(?:\s+(?:them|the\s+top|of\s+them|both))?"
            r"(?:,?\s+(?:connecting|joining|linking)\s+(?:them|both|the\s+two)(?:\s+of\s+them)?)?\b",
            re.IGNORECASE,
        ),
        " {0}{1} joined at the top by a {2} ",
        "read '{0}' as the towers joined by the beam",
    ),
    (  # "two columns of two and one beam": the beam said last, with no verb of its own, lies across
        # them (it was dropped; "… and bridge them with a beam" is read by its verb)
        re.compile(
            r"\b(towers?|pillars?|columns?|stacks?|posts?|uprights?)\b((?:(?!\b(?:with|bridge\w*|join\w*|"
            r"connect\w*|span\w*|link\w*)\b)[^.;])*?)\s*,?\s*\b(?:and|plus)\s+(?:a|one|an)\s+(beam|plank|"
            r"lintel|girder|bar|deck)(?=\s*(?:[.;]|$))",
            re.IGNORECASE,
        ),
        " {0}{1} joined at the top by a {2} ",
        "read '{0}' as the towers joined by the beam",
    ),
    (  # "two towers joined by a beam and a cube on top", "…, a cube on the beam": what follows
        # is a structure of its own (read with the beam as what joins the towers; the cube stood
        # between them)
        re.compile(
            r"\b(joined\s+(?:at\s+the\s+top\s+)?by\s+(?:a|one|the)\s+(?:beam|lintel|plank|girder|"
            r"crossbar))\s*(?:,\s*(?:and\s+)?|\s+and\s+)(?=(?:then\s+)?(?:(?:put|place|add|set|"
            r"stand)\s+)?(?:an?\b|one\s+(?:single\s+)?(?:cube|block|tower)\s+on\b))",
            re.IGNORECASE,
        ),
        "{0}, then ",
        "",
    ),
    (  # "two stacks of two, a beam across their tops, and on the beam a stack of three": what
        # stands on the beam, said after it (it stood apart, silently)
        re.compile(
            r"\s*[,;]?\s*(?:and\s+)?(?:then\s+)?(on(?:\s+top\s+of)?\s+(?:that|the|this)\s+(?:beam|"
            r"lintel|crossbar|plank|girder))\s*,?\s+(?=(?:put\s+|place\s+|stand\s+|set\s+)?(?:an?|one|"
            r"\d+)\b)",
            re.IGNORECASE,
        ),
        ". {0} ",
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
        re.compile(r"\b(?:actually|sorry|oops|wait)\b\s*,?\s*(?:no\b\s*,?)?", re.IGNORECASE),
        " then ",
        "",
    ),
    (
        re.compile(r",?\s*\bnothing\s+(?:big|large|huge|tall|fancy|special)\b", re.IGNORECASE),
        " ",
        "",
    ),
    (  # "one half its height", "twice the height": the number said last, changed
        re.compile(
            r"\b(twice|double|half|(?:\d+|two|three|four|five)\s+times)\s+(?:of\s+)?(?:its|the|their|that)\s+"
            r"(height)\b(?!\s+of)",
            re.I,
        ),
        "{compared}",
        "",
    ),
    (  # "the other one twice that": the number said last, changed
        re.compile(
            r"(?<=\bone\s)(twice|double|thrice|half)\s+(?:of\s+)?(that)\b(?!\s+(?:height|size))",
            re.IGNORECASE,
        ),
        "{compared}",
        "",
    ),
    (  # "one twice as tall" (as the one before): the number said last, changed
        re.compile(
            r"\b(twice|double|thrice|half|just|exactly|equally|(?:\d+|two|three|four|five)\s+times)\s+as\s+"
            r"(tall|high|big|large|long)\b(?!\s+as\b(?!\s+(?:it|that|the\s+other|the\s+first)"
            r"(?:\s+one)?\b))",
            re.IGNORECASE,
        ),
        "{compared}",
        "",
    ),
    (  # "another one with one less", "a second one a cube taller"
        re.compile(
            r"\bwith\s+(?:just\s+|only\s+)?(?:a|(\d+|one|two|three|four|five))\s+"
            r"(?:cubes?\s+|parts?\s+|blocks?\s+)?(more|fewer|less)\b(?:\s+(?:cubes?|parts?|blocks?))?"
            r"(?!\s+(?:than|\w+s\b))|"
            r"\b(?:a|(\d+|one|two|three|four|five))\s+(?:cubes?\s+|parts?\s+|levels?\s+|blocks?\s+|steps?\s+)?"
            r"(taller|higher|shorter|lower)\b(?!\s+than)",
            re.IGNORECASE,
        ),
        "{compared}",
        "",
    ),
    (
        re.compile(
            r"\b(twice|double|thrice|half|(?:\d+|two|three|four|five)\s+times)\s+as\s+"
            r"(tall|high|long|wide)\s+as\s+(?:a\s+)?"
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
        re.compile(
            r"(?<!by\s)\b(\d+(?:\.\d+)?\s*(?:cm|mm|m|inches|inch|in|ft|feet|foot))\s+square\b",
            re.IGNORECASE,
        ),
        " {0} by {0} ",
        "",
    ),
    (
        re.compile(r"\b(steps|levels|layers|storeys|floors|tiers|spans)\s*[:=]\s*(\d+)\b", re.I),
        " {1} {0} ",
        "",
    ),
    (
        re.compile(r"(?<!\b[ltu][\s-])\b(?:shape|structure|type|kind|item|object)\s*[:=]\s*",
                   re.IGNORECASE),  # not "U-shape:", a heading of its own
        " a ",
        "",
    ),
]


_OPEN = re.compile(
    r"\b(?:(tall|high|big|large)\s+)?(structure|thing|something|shape|construction|object|"
    r"build|sculpture|monument)\s+(?:that\s+is\s+\w+\s+)?with\s+a\s+(wide|broad|big|large|"
    r"wider|broader|heavy|solid)\s+(base|bottom|foot|footing|foundation)\b",
    re.IGNORECASE,
)


_ADJECTIVE_ONE = re.compile(
    r"\b(an?\s+(?:little|small|smaller|short|shorter|low|lower|tall|taller|high|higher|big|bigger|"
    r"large|larger|long|longer|wide|wider|tiny|mini))\s+one\b"
    r"(?!\s+(?:of\s+(?:them|those|these|the)|cube|block)\b)",
    re.IGNORECASE,
)
_TOUCH_ANOTHER = re.compile(
    r"\b(touch(?:es|ing)?|meet(?:s|ing)?|lean(?:s|ing)?\s+on|against|from)\s+another\s+one\b", re.I
)
_ANOTHER = re.compile(
    r"\b(?:(?:another|one\s+more|a\s+second|a\s+third|a\s+fourth)\s+(?:identical\s+|similar\s+|"
    r"matching\s+)?one\b|an?\s+(?:identical|matching|similar)\s+one\b|a\s+(?:third|fourth|fifth)\b"
    r"(?!\s+(?:as|of|level|layer|tier|row|storey))|(?<=,\s)(?:one|1)(?=\s+(?:on|at|in|to)\s+the\b)|"
    r"(?<=\band\s)(?:one|1)(?=\s+(?:(?:on|at|in|to)\s+(?:the|its)\b|(?:behind|beside|next\s+to|"
    r"in\s+front\s+of)\s+(?:it|them)\b))|"
    # "and another with double the height", "another 6 high", "and another, a bit lower"
    r"\banother(?=\s*(?:$|[,.;]|\s(?:with|of|that|which|having|at|on|in|next|behind|beside|\d+|"
    r"to(?=\s+(?:its|the|their)\s+(?:left|right)\b)|"  # "and another to its right"
    r"two|three|four|five|six|seven|eight|nine|ten)\b(?!\s+by\s))))",  # not "another two by two"
    re.IGNORECASE,
)


_LEGS = re.compile(r"\blegs?\b", re.IGNORECASE)


_TOP = re.compile(r"\b(?:top|roof|tabletop|surface|lid)\b", re.IGNORECASE)


_ARTICLES = frozenset({"a", "an", "another", "the", "it", "them", "one", "two", "three"})


_SIZE2 = r"\d+(?:\.\d+)?\s*(?:x|by)\s*\d+(?:\.\d+)?(?:\s*(?:mm|cm|m)\b)?"
_SIZED_TOP = re.compile(
    rf"(?:\s*(?:,|;|:|\band\b|\bwith\b|\n\s*-)\s*)?(?:(?:an?|the|its)\s+)?"
    rf"(?:({_SIZE2})\s+(?:top|roof|deck|tabletop)\b|"
    rf"\b(?:top|roof|deck|tabletop)\s*(?:of\s+|:\s*)?(?:(?:about|around|roughly|approx\w*)\s+)?"
    rf"({_SIZE2})(?:\s+(?:cubes?|parts?|blocks?)\b)?)",
    re.IGNORECASE,
)
"""'a pavilion with legs 3 high and a 20 by 20 cm roof', "… Top about 4 by 4 cubes": the size
of a table's own top."""


def _sized_top(text: str) -> str:
    """A canopy's top, roof or deck said with its size after the canopy is the canopy's size
    (said after its legs it was read as a block of its own, or its size went with the noun):
    the size goes next to the canopy's name (no bridge or arch said)."""
    named = [
        m for m in re.finditer(r"[a-z]+", text, re.IGNORECASE)
        if lx.SHAPE_WORDS.get(m.group(0).lower()) in ("canopy", "bridge", "arch")
        and m.group(0).lower() not in ("roof", "deck")  # the top itself
    ]  # fmt: skip
    if len(named) != 1 or lx.SHAPE_WORDS.get(named[0].group(0).lower()) != "canopy":
        return text
    top = [m for m in _SIZED_TOP.finditer(text) if m.start() >= named[0].end()]
    if len(top) != 1:
        return text
    m = top[0]
    size = m.group(1) or m.group(2)
    end = named[0].end()
    rest = text[end : m.start()] + text[m.end() :]
    return f"{text[:end]} with a {size} top{'' if rest[:1] in ',.;:' else ','}{rest}"


_ONE_MORE = re.compile(
    r"(?<!\boff\s)(?<!\baway\s)"  # "take off one more": a change, not another structure
    r"(?<!\bsecond\s)(?<!\bother\s)(?<!\bthird\s)"  # "the second one more": a size of it
    r"\b(?:and\s+|then\s+|plus\s+)?(?:just\s+)?one\s+more\b(?!\s+(?:cube|block|brick|part|level|"
    r"layer|step|row|course|tier|time|of)\w*)",
    re.IGNORECASE,
)
"""'… and one more next to that': another of the structure named before."""


_COUNTED_TOWER = re.compile(
    r"\b(?:a|one|the)\s+(?:(?:single|small|little|tall)\s+)?(?:tower|stack|column|pile)\s+(?:of\s+)?"
    r"(?:\d+|two|three|four|five|six|seven|eight|nine|ten)(?:\s+(?:cubes?|blocks?))?"
    r"(?![^.;!?]*\b(?:towers|stacks|columns|piles|and\s+(?:a|an|one|two|three)\s)\b)",
    re.IGNORECASE,
)
"""'a tower of three' (one, its cubes counted): 'then add one more' is one more cube on it."""
_ON_IT = re.compile(r"\b(?:on(?:to)?\s+(?:top|it|that|this)|on\s+the\s+top|atop)\b", re.I)
_PLACED = re.compile(r"\b(?:next|beside|behind|front|left|right|side|apart|away|another)\b", re.I)


def _one_more(m: re.Match[str], text: str) -> str:
    """ "a tower of 3. Then put on it one more. And one more.": one more cube on top when
    the step stacks onto a tower (or repeats a step that did); otherwise another structure."""
    start = max(text.rfind(c, 0, m.start()) for c in ".;!?\n")
    step = text[start + 1 : m.start()]
    step_end = min([i for i in (text.find(c, m.end()) for c in ".;!?\n") if i >= 0] or [len(text)])
    after = text[m.end() : step_end]
    before = text[: start + 1]
    if re.search(r"\b(?:add|put|stick|tack|stack)\s*$", step, re.I) and re.match(
        r"\s*(?:to|on|onto|at)\s+(?:it\b|(?:the|its)\s+(?:other\s+)?(?:end|row|line|wall|tower|stack|"
        r"column|top)\b)", after, re.I
    ):
        return " one more cube "  # "a row of 4, then add one more to the end": a cube of it
    if (
        _COUNTED_TOWER.search(before + step)
        and re.search(r"\b(?:add|stack|put|pop|place)\s*$", step, re.I)
        and not after.strip(" ,.!")
    ):
        return " one more cube "  # "build a tower of three then add one more": a cube on it
    words = re.findall(r"[a-z]+", before.lower())
    shapes = [w for w in words if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES]
    tower = bool(shapes) and shapes[-1] in ("tower", "towers", "stack", "column", "pillar")
    named = any(w in lx.SHAPE_WORDS for w in re.findall(r"[a-z]+", (step + after).lower()))
    if tower and not named and not _PLACED.search(step + after):
        if _ON_IT.search(step + after):
            return " one more cube "  # "then put on it one more"
        last_step = before[max(before.rfind(c, 0, len(before) - 1) for c in ".;!?\n") + 1 :]
        if re.search(r"\bone\s+more\b", last_step, re.I) and _ON_IT.search(last_step):
            return " one more cube on top "  # "… then put one more on top. Then one more!"
    if re.match(r"\s*on\b(?!\s+the\s+(?:left|right|back|front|other))", after, re.I):
        return m.group(0)  # "a row, another on top, and one more on top": stacked after
    return " and another one"


_BARE_SIZE = re.compile(
    r"\b(a|an|one|another)\s+(\d+\s+x\s+\d+(\s+x\s+\d+)?)(?=\s*(?:[,.;]|$|\b(?:on|onto|above|"
    r"atop|then|and|at|in|next|beside|behind|to)\b))",
    re.IGNORECASE,
)


def _bare_size(text: str, st: ReadState) -> str:
    """ "a 3x3 base with a 2x2 on it": a size with its noun left out after a structure named
    is another of its kind — a layer (a block when three sizes are said)."""

    def sub(m: re.Match[str]) -> str:
        said = re.findall(r"[a-z]+", text[: m.start()].lower())
        shapes = [w for w in said if w in lx.SHAPE_WORDS or w in ("base", "foundation", "footing")]
        if not shapes:
            return m.group(0)  # "build a 2x2": the grammar's own bare size
        noun = "block" if m.group(3) else "layer"
        st.notes.append(f"read '{m.group(0)}' as {m.group(1)} {m.group(2)} {noun}")
        return f"{m.group(0)} {noun}"

    return _BARE_SIZE.sub(sub, text)


_ATTRIBUTIVE = re.compile(
    r"\b(?P<art>a|an|one)\s+(?:(?:little|slightly|much|bit)\s+)?(?P<cmp>smaller|bigger|larger|taller|"
    r"shorter|higher|lower|longer|wider|narrower)\s+(?=[a-z0-9])",
    re.IGNORECASE,
)
_MORE = ("bigger", "larger", "taller", "higher", "longer", "wider")


def _attributive(text: str, st: ReadState) -> str:
    """ "a tower of 5 and a smaller tower of 3", "on it a smaller 2x2 slab": a comparative
    said with the structure's own size is a claim about it — checked against the number said
    last before, never a size of its own."""

    def sub(m: re.Match[str]) -> str:
        own = re.split(r"[,.;]|\band\b", text[m.end() :])[0]
        said = re.search(r"\d+", own)
        if not said or not re.search(r"[a-z]", own[: said.start()] + own[said.end() :]):
            return m.group(0)  # "a smaller one": the comparison handlers' own
        before = re.findall(r"\d+", COUNTED.sub(" ", text[: m.start()]))
        word = m.group("cmp").lower()
        # "a bigger one of 4": "one of 4" (not "a one of 4", read as nothing)
        art = "" if re.match(r"one\b", text[m.end() :], re.I) else f"{m.group('art')} "
        if before:
            new, old = int(said.group(0)), int(before[-1])
            if (new > old) != (word in _MORE) or new == old:
                st.material.append(word)
                st.notes.append(f"ignored '{word}': {new} is not {word} than the {old} said "
                                "before")  # fmt: skip
                return art
            st.notes.append(f"'{word}': holds ({new} against the {old} said before)")
        return art

    return _ATTRIBUTIVE.sub(sub, text)


_BEAM_SIZE = re.compile(
    r"\b(?:(?P<n>\d+)[- ](?:cube|block|part)s?[- ](?:long[- ])?|(?P<m>\d+(?:\.\d+)?)\s*"
    r"(?P<u>mm|cm|m)[- ](?:long\s+)?)(?P<beam>beams?|planks?|girders?|lintels?)\b"
    r"|\b(?P<beam2>beams?|planks?|girders?|lintels?)\s+(?:of\s+(?P<n2>\d+)\s+(?:cube|block|part)s?"
    r"(?:\s+long)?|(?P<n3>\d+)\s+(?:cube|block|part)s?\s+long|(?P<m2>\d+(?:\.\d+)?)\s*"
    r"(?P<u2>mm|cm|m)\s+long)\b",
    re.IGNORECASE,
)


def _beam_size(text: str, st: ReadState) -> str:
    """ "a 3-cube beam across the top", "a lintel 15 cm long": the length of SDI's one beam
    part, said and checked — any other length is reported, never silently dropped."""
    cube = st.cell.cube[0]
    beam_m = st.cell.part_types.get("beam", (0.0,))[0]  # the cell's beam part (0.15 m)
    cubes_long = f"{beam_m / cube:g} cubes"

    def sub(m: re.Match[str]) -> str:
        beam = m.group("beam") or m.group("beam2")
        said = m.group(0).strip()
        if m.group("m") or m.group("m2"):
            unit = (m.group("u") or m.group("u2")).lower()
            cubes = float(m.group("m") or m.group("m2")) * lx.UNITS_M[unit] / cube
        else:
            cubes = float(m.group("n") or m.group("n2") or m.group("n3"))
        if beam_m and abs(cubes - beam_m / cube) < 0.05:
            st.notes.append(f"read '{said}' as SDI's beam ({cubes_long}, {beam_m:g} m long)")
        else:
            st.material.append(said)
            has = f"SDI's beam is {cubes_long} ({beam_m:g} m) long" if beam_m else "no beam part"
            st.notes.append(f"ignored the length in '{said}': {has}")
        return f" {beam} "

    return _BEAM_SIZE.sub(sub, text)


_SPANNED = "|".join(sorted(
    (w for w, f in lx.SHAPE_WORDS.items()
     if f in ("bridge", "arch") and w not in ("lintel", "roof")),
    key=len, reverse=True))  # fmt: skip
_OWN_LINTEL = re.compile(
    r"\b((?:" + _SPANNED + r")\b[^.;]*?\b(?:posts?|pillars?|legs?|columns?|towers?|sides?|"
    r"supports?|piers?|uprights?|jambs?)\b[^.;]*?)\b(lintel|crossbar)\b",
    re.IGNORECASE,
)
"""'a doorway with sides four cubes tall and a lintel across': the doorway's own beam (its
lintel was read as a second bridge, silently)."""

_BEAM_HELD = re.compile(
    r"\b(beams?|lintels?|planks?|girders?|crossbars?)\s+(?:supported|held(?:\s+up)?|carried|"
    r"borne|propped(?:\s+up)?)\s+by\s+",
    re.IGNORECASE,
)
"""'a beam supported by two towers of 3': the beam rests on them (it was dropped)."""


_ONE_SIZED = re.compile(
    r"\b(?:one|1)\s+(?=(?:(?:really|very|quite|pretty|super|extra|nice|single|"
    + "|".join(sorted(lx.SIZE_WORDS, key=len, reverse=True))
    + r")[\s,]+)+(?:" + shape_alternation(exclude=lx.AMBIGUOUS_SHAPES) + r")\b(?![\s-]*shaped))",
    re.IGNORECASE,
)
"""'one tall tower', 'one big tower': one of them, of that size (read as 1 high, silently)."""


_FOR_USE = re.compile(
    r"\s*,?\s*\bfor\s+(?:my|our|his|her|their|the|your|this|that)\s+(?:[a-z]+\s+){0,2}?(?:"
    + shape_alternation(exclude=lx.AMBIGUOUS_SHAPES, min_len=3)
    + r")(?:\s+[a-z-]+){0,2}?(?=\s*(?:[,.;:!?]|$))",
    re.IGNORECASE,
)


def _for_use(text: str, st: ReadState) -> str:
    """ "a little wall for my garden scene": what the structure is for, not one more (a garden
    enclosure was built and given the wall's sizes, silently)."""

    def sub(m: re.Match[str]) -> str:
        if not families_said(text[: m.start()]) or re.search(rf"\d|\b{_N}\b", m.group(0), re.I):
            return m.group(0)  # "build one for the garden": the word is all there is
        st.notes.append(f"read '{m.group(0).strip(' ,')}' as what it is for, not a structure")
        return " "

    return _FOR_USE.sub(sub, text)


_ARCH_WORD = re.compile(r"\barch(?:way)?(e?s)?\b", re.IGNORECASE)
_POSTS = re.compile(r"\b(?:pillars?|posts?|legs?|columns?|uprights?|piers?|stacks?|towers?)\b",
                    re.IGNORECASE)
_BEAM_WORD = re.compile(r"\b(?:beams?|lintels?|crossbars?|planks?|girders?)\b", re.IGNORECASE)
_CURVED = re.compile(r"\b(?:corbel\w*|curv\w*|round\w*|stepped|pointed|semi-?circular)\b", re.I)


def _post_and_beam(text: str, st: ReadState) -> str:
    """ "a small archway: two pillars of three, a beam across": an arch said by its posts and
    beam is those posts and that beam — SDI's bridge (SDI's arch steps corbels in under its beam,
    and was built 5 high on legs of 3, silently)."""
    out = []
    for sentence in re.split(r"(?<=[.;!?])", text):
        said = _ARCH_WORD.search(sentence)
        if (
            said
            and _POSTS.search(sentence)
            and _BEAM_WORD.search(sentence)
            and not _CURVED.search(sentence)
        ):
            st.notes.append(f"read '{said.group(0)}' of posts and a beam as a bridge: posts and "
                            "the beam across them (SDI's arch steps corbels in under its beam)")
            sentence = _ARCH_WORD.sub(lambda m: "bridge" + ("s" if m.group(1) else ""), sentence)
        out.append(sentence)
    return "".join(out)


_SINGLE_LAYER = re.compile(
    r"\b(?:a|one)\s+(?:single|flat|one[- ]cube[- ]thick)\s+layer\s+of\s+(?:cubes|blocks|parts)\b",
    re.I,
)


def _single_layer(text: str) -> str:
    """ "fill the front left with a single layer of cubes": a layer, when nothing else in the
    command is the structure it would be the height of."""
    m = _SINGLE_LAYER.search(text)
    rest = re.sub(r"\bthe\s+table\b", " ", text[: m.start()] + text[m.end() :]) if m else ""
    if m and not any(w in lx.SHAPE_WORDS for w in re.findall(r"[a-z]+", rest.lower())):
        return f"{text[: m.start()]}a layer of cubes{text[m.end() :]}"
    return text


_SIZED_BASE = re.compile(
    r"(?<![\w.])(?:(?P<art>a|an|one|the)\s+)?(?P<size>\d+\s+x\s+\d+(?P<third>\s+x\s+\d+)?)\s+"
    r"(?P<noun>base|foundation|footing)\b(?!\s+(?:of|for|to)\b)"
    r"(?:\s+(?P<own>layer|slab|plate|pad|block|platform)\b)?",
    re.IGNORECASE,
)


def _sized_base(text: str, st: ReadState) -> str:
    """ "a 4x4 base and a tower of 3 on it", "a tower of 3 on a 4x4 base": a base with sides of
    its own is a slab (a block, three sizes said) — not the base of a pyramid said with it
    ("a pyramid with a 4x4 base", "whose base is 4x4")."""

    def sub(m: re.Match[str]) -> str:
        sentence = re.split(r"[.;!?]\s", text[: m.start()])[-1]  # "Pyramid: 4x4 base": its own
        before = re.findall(r"[a-z]+", sentence.lower())
        if {"with", "whose", "its", "has", "having", "of", "their"} & set(before[-1:]):
            return m.group(0)
        shapes = [lx.SHAPE_WORDS[w] for w in before if w in lx.SHAPE_WORDS]
        if shapes[-1:] == ["pyramid"]:
            return m.group(0)  # "a 3-level pyramid on a 4x4 base": the pyramid's own
        noun = m.group("own") or ("block" if m.group("third") else "slab")
        art = m.group("art") or "a"
        st.notes.append(f"read '{m.group(0).strip()}' as {art} {m.group('size')} {noun}")
        made.append(noun)
        return f"{art} {m.group('size')} {noun}"

    made: list[str] = []
    text = _SIZED_BASE.sub(sub, text)
    pyramid = families_said(text).count("pyramid")  # a pyramid's base is its own
    if len(made) == 1 and not pyramid:  # "a 3x3 base. Place a cube on the base": on that slab
        text = re.sub(r"\b(the|that|this)\s+base\b(?!\s+of\b)", rf"\1 {made[0]}", text, flags=re.I)
    return text


_OWN_PARTS = re.compile(
    r"(\b(?:bridge|table|arch|gate|canopy|bench|gateway|doorway|portal|shelter)s?\s+(?:with|"
    r"having)\s+(?:[\w-]+\s+){0,3}?)(?:posts?|legs?|pillars?|supports?|columns?|uprights?)\b",
    re.IGNORECASE,
)
"""A roofed structure said with its parts ("a bridge with posts of 2"): the parts are its own,
no family a later "another one" repeats."""


def _another(text: str) -> str:
    """ "a tower on the left and another one on the right": another tower."""
    text = _ONE_MORE.sub(lambda m: _one_more(m, text), text)
    text = _TOUCH_ANOTHER.sub(r"\1 each other", text)  # "none may touch another one": no new one

    def adjective_one(m: re.Match[str]) -> str:  # "and next to it a little one": a little tower
        said = re.findall(r"[a-z]+", text[: m.start()].lower())
        nouns = [w for w in said if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES]
        added = said[-1:] == ["it"] or {"and", "then", "plus", "also"} & set(said[-5:])
        if not nouns or not added or "not" in said[-2:]:  # "the pyramid, a small one please",
            return m.group(0)  # "but not a big one": the same structure, not a second
        noun = nouns[-1][:-1] if nouns[-1][:-1] in lx.SHAPE_WORDS else nouns[-1]
        return f"{m.group(1)} {noun}"

    text = _ADJECTIVE_ONE.sub(adjective_one, text)

    def sub(m: re.Match[str]) -> str:
        # "a bridge with posts 2 …, then another one": the posts are the bridge's own
        said = re.findall(r"[a-z]+", _OWN_PARTS.sub(r"\1", text[: m.start()]).lower())
        before = [
            w
            for k, w in enumerate(said)
            if w in lx.SHAPE_WORDS
            and w not in lx.AMBIGUOUS_SHAPES
            # "one of 4 in the middle of the table and one of 6": the table is a place
            and not (w == "table" and said[k - 2 : k] in (["of", "the"], ["on", "the"]))
            # "now stack a second one": the verb is not the noun it repeats
            and not (w in lx.VERB_SHAPES and (k == len(said) - 1 or said[k + 1] in _ARTICLES))
        ]
        if not before:
            parts = [
                w
                for w in said
                if w in lx.PART_WORDS or (w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES)
            ]
            if re.search(r"\d\s*(?:x|by)\s*\d+\s+blocks?\b|\bblocks?\s+\d+\s+(?:high|tall)\b",
                         text[: m.start()], re.I):  # fmt: skip
                return "another block"  # "a 2x2 block 3 high …, then put another one"
            if parts and parts[-1] in ("cube", "cubes", "block", "blocks", "brick", "bricks"):
                return "another 1-cube tower"  # "a cube in each corner and 1 in the middle"
            return m.group(0)
        noun = before[-1]
        noun = noun[:-1] if noun.endswith("s") and noun[:-1] in lx.SHAPE_WORDS else noun
        return f"another {noun}"

    return _ANOTHER.sub(sub, text)


# "two towers of 3, one at the far left, one at the far right" (handler: one item per copy)
_CLOSE_TO_IT = r"(?:\s*,?\s*(?:close|near|right|next)\s+(?:to\s+)?it\b)?"
"""', close to it' after an edge: the edge, said again."""

_REWRITES += [
    # "a 3x3 pad with a 2x2 pad on top of it and a cube on top of that": after a relation's
    # pronoun, "and a …" starts the next structure (its own clause)
    (
        re.compile(
            r"\b(on\s+top\s+of|on|onto|next\s+to|beside|behind|in\s+front\s+of|around|inside)\s+"
            r"(it|them|that|those)\s*,?\s+and\s+(?:then\s+)?(?=(?:a|an|one|another)\s)",
            re.IGNORECASE,
        ),
        " {0} {1}. Then ",
        "",
    ),
    # "directly behind it", "dead centre", "right next to": an intensifier of a place
    (
        re.compile(
            r"\b(?:directly|immediately|dead|exactly|right(?!\s+to\s+left\b)|just|squarely)\s+(?=(?:behind|in\s+front|"
            r"next\s+to|beside|to\s+(?:the\s+|its\s+)?(?:left|right)|on\s+top|above|atop|"
            r"(?:in\s+the\s+)?(?:centre|center|middle))\b)",
            re.IGNORECASE,
        ),
        "",
        "",
    ),
    # "after that, the same again at the back right": another of the one before
    (re.compile(r"\bapiece\b", re.IGNORECASE), " each ", ""),
    (re.compile(r"\ball\s+the\s+way\s+(?:a?round|about)\b", re.IGNORECASE), " around ", ""),
    # "bump it up another course": raise it by another layer
    (
        re.compile(
            r"\b(?:bump|jack|build|push|bring|take)\s+(it|them)\s+up\s+(?:by\s+)?(?:another|one\s+more|"
            r"an\s+extra)\s+(?:course|layer|level|row|tier)\b",
            re.IGNORECASE,
        ),
        " raise {0} by another layer ",
        "",
    ),
    # "wall: eighteen cubes, 6 per course": the parts in each layer are its length
    (
        re.compile(
            r"\b(\d+|two|three|four|five|six|seven|eight|nine|ten)\s+(?:cubes?\s+|parts?\s+)?"
            r"(?:per|in\s+each|on\s+each|a)\s+(?:course|layer|row|level|tier)\b",
            re.IGNORECASE,
        ),
        " {0} long ",
        "read '{0}' as the parts in each course (its length)",
    ),
    # "a row that does not run left to right": the other horizontal direction
    (
        re.compile(
            r"\b(?:that\s+|which\s+)?(?:does|do)\s+not\s+(?:run|go|extend|point|lie)\s+"
            r"(?:from\s+)?(left\s+to\s+right|side\s+to\s+side|front\s+to\s+back|back\s+to\s+front)\b",
            re.IGNORECASE,
        ),
        "{not_axis}",
        "",
    ),
    # The choice left to SDI: "whatever size works", "your call on sizes", "at your
    # discretion", "surprise me", "I don't care how many steps" (the defaults are used)
    (
        re.compile(
            r"(?:,\s*)?\b(?:(?:of\s+|in\s+)?(?:whatever|any)\s+(?:size|sizes|height|heights|shape|"
            r"shapes|form|proportions?|kind|design|dimensions?|number\s+of\s+\w+)"
            r"(?:\s+(?:you\s+(?:like|want|think|choose|prefer|fancy)|(?:that\s+)?works|is\s+fine))?"
            r"|(?:at\s+(?:your|the\s+operator'?s?)\s+discretion)"
            r"|(?:(?:of\s+|in\s+)?your\s+(?:own\s+)?(?:choice|call|pick|design|proportions|"
            r"preference)(?:\s+on\s+(?:the\s+)?\w+)?)"
            r"|up\s+to\s+you|(?:you|sdi|the\s+robot)\s+(?:can\s+|may\s+)?(?:decide|choose|pick)"
            r"(?:\s+the\s+(?:(?:tower|wall|stack|row|pyramid|bridge)\s+)?(?:form|shape|size|sizes|"
            r"design|height|length|width|number\s+of\s+\w+))?"
            r"|how(?:ever)?\s+you\s+(?:want|like)|as\s+you\s+(?:like|wish|see\s+fit)"
            r"|free\s+design|dealer'?s\s+choice|surprise\s+me(?:\s+with)?"
            r"|i\s+do\s*n[o']?t\s+(?:care|know|mind)\s+(?:how\s+(?:many|big|tall|high|long|wide)"
            r"(?:\s+\w+)?|about\s+the\s+\w+)"
            r"|ur\s+choice|(?:just\s+)?whatever(?:\s+you\s+(?:like|want|think))?"
            r"|(?:you\s+)?(?:pick|choose|select|decide\s+on)\s+(?:a|the|any)\s+"
            r"(?:(?:tower|wall|stack|row|pyramid|bridge)\s+)?(?:height|size|length|number\s+of\s+\w+)"
            r"|anything(?:\s+you\s+(?:like|want))?|something\s+(?:fun|nice|cool|interesting|"
            r"pretty|creative|different|quick|simple))\b",
            re.IGNORECASE,
        ),
        "{delegated}",
        "",
    ),
    # Against a side of the workspace: "hugging the right boundary", "flush with the back
    # edge", "parallel to the left edge, close to it", "as far back as it can go", "all the
    # way to the left", "at the back, the furthest it can" (the grammar reads "at the back
    # edge" into the structure's `edge`)
    (  # "parallel to the left edge": it runs front to back, along that edge
        re.compile(r"\bparallel\s+(?:to|with)\s+the\s+(left|right)\s+edge\b" + _CLOSE_TO_IT, re.I),
        " along x at the {0} edge ",
        "read '{0}' as running front to back against that edge of the workspace",
    ),
    (
        re.compile(r"\bparallel\s+(?:to|with)\s+the\s+(back|front)\s+edge\b" + _CLOSE_TO_IT, re.I),
        " along y at the {0} edge ",
        "read '{0}' as running left to right against that edge of the workspace",
    ),
    (
        re.compile(
            r"\b(?:(?:right|up|snug|tight)\s+)*(?:hugging|flush\s+(?:with|against|to)|against|"
            r"along|alongside|touching|close\s+to|next\s+to|near|by)\s+the\s+"
            r"(left|right|back|front)\s+(?:edge|boundary|border|limit)"
            r"(?:\s+of\s+the\s+(?:table|workspace|work\s*space|work\s*area|cell|area))?"
            + _CLOSE_TO_IT,
            re.IGNORECASE,
        ),
        "{edge}",
        "",
    ),
    (
        re.compile(
            r"\b(?:(?:pushed|moved|shoved|slid|placed|set|put)\s+)?as\s+far\s+"
            r"(?:to\s+the\s+|towards?\s+the\s+|over\s+to\s+the\s+)?"
            r"(left|right|back|front|forwards?|backwards?)\s+as\s+(?:[\w']+\s+){0,3}?"
            r"(?:go|goes|get|gets|possible|fit|fits|reach|reaches|allowed|permitted|can)\b"
            r"(?:\s+(?:go|get|fit|reach))?",
            re.IGNORECASE,
        ),
        "{edge}",
        "",
    ),
    (
        re.compile(
            r"\ball\s+the\s+way\s+(?:to\s+the\s+|at\s+the\s+|over\s+to\s+the\s+|"
            r"(?:to\s+the\s+)?)(left|right|back|front)\b",
            re.IGNORECASE,
        ),
        "{edge}",
        "",
    ),
    (
        re.compile(
            r"\b(?:far\s+(?:away\s+)?)?(?:at|to|in|on)\s+the\s+(left|right|back|front)\s*,?\s*"
            r"(?:the\s+|as\s+)?(?:furthest|farthest|far)\s+(?:as\s+)?(?:[\w']+\s+){0,2}?"
            r"(?:can|possible|go|goes)\b(?:\s+go)?",
            re.IGNORECASE,
        ),
        "{edge}",
        "",
    ),
]


_BEAMED = "|".join(
    sorted(
        (w for w, f in lx.SHAPE_WORDS.items() if f in ("bridge", "arch") and w.isalpha()),
        key=len,
        reverse=True,
    )
)
# "gate with two posts 4 high and a beam over them": the beam is the gate's own
_OWN_BEAM = re.compile(
    r"\b(" + _BEAMED + r")\b([^.;]*?)\s*,?\s*\band\s+(?:a|one|the)\s+(?:beam|lintel|slab|deck|top)"
    r"\s+"
    r"(?:on\s+top(?:\s+of\s+(?:them|the\s+\w+))?|over\s+(?:them|the\s+top)|across\s+"
    r"(?:them|the\s+top)|spanning\s+them|resting\s+on\s+them)",
    re.IGNORECASE,
)
_TALL_NOUN = re.compile(r"\b(?:skyscraper|spire|obelisk|high-?rise)s?\b", re.IGNORECASE)
# "a solid block 100 mm on every side" (handler: all three sides of a block)
_EVERY_SIDE = re.compile(
    r"\b(\d+(?:\.\d+)?\s*(?:mm|cm|m)|\d+\s+(?:cubes?|parts?))\s+(?:on|along|to)\s+"
    r"(?:every|each|all|a)\s+(?:sides?|edges?)\b",
    re.IGNORECASE,
)
_LIKE_THAT = re.compile(
    r"\banother\s+(?:one\s+)?(?:just\s+|exactly\s+)?like\s+(?:that|it|this|the\s+(?:first|last|"
    r"previous|other)(?:\s+one)?)\b|\b(?:duplicate|copy|clone)\s+(?:it|that|this)\b",
    re.IGNORECASE,
)
"""'And another like that, behind it', 'duplicate it 1 cube to the left': another of the
one named before."""
_SAME_AS_BEFORE = re.compile(
    r"\b(?:an?|one)\s+([a-z]+)\s+(?:just\s+|exactly\s+)?(?:like|the\s+same\s+as|identical\s+to)\s+"
    r"(?:that(?:\s+one)?|it|this(?:\s+one)?|the\s+(?:first|last|previous|other)(?:\s+one|\s+[a-z]+)?)\b",
    re.IGNORECASE,
)
"""'a tower of 3 and a tower like the first one': another of the one named before."""
_SAME_AGAIN = re.compile(
    r"\b(?:the\s+)?same\s+(?:again|once\s+more|one\s+again)\b(?:\s*,?\s*but\b)?"
    r"|\b(?:one|another(?:\s+one)?)\s+(?:just\s+)?the\s+same\s+as\s+(?:before|the\s+first(?:\s+one)?|that"
    r"(?:\s+one)?)\b(?:\s*,?\s*but\b)?",  # "now one the same as before on the right"
    re.I,
)
_DISTRIBUTE = re.compile(
    r"\b(two|three|four|five|[2-5]|both|a\s+(?:couple|pair)\s+of)\s+((?:[\w-]+\s+)?"
    r"(?:\d+\s*(?:x|by|×)\s*\d+(?:\s*(?:x|by|×)\s*\d+)?\s+)?)("
    + _SHAPE_ALT + r")s\b"
    r"((?:\s+(?:of|with)\s+[\w\s-]+?|(?:\s*,?\s*(?:and\s+)?(?:\d+|one|two|three|four|five|six)\s+"
    r"(?:cubes?\s+)?(?:high|tall|long|wide|thick|deep|layers?|levels?|courses?|tiers?))+"
    r"(?:\s+(?:each|apiece))?|\s+(?:high|tall|long|wide)\s+(?:\d+|two|three|"
    r"four|five|six))?)"
    r"(?P<together>\s+(?:side\s+by\s+side|next\s+to\s+each\s+other|in\s+a\s+row|in\s+(?:a\s+)?line))?"
    r"(?:\s*,?\s*please)?(?:\s*[:,;]\s*|\s+(?=one\s+(?:at|on|in)\s+the\s))(?P<items>(?:one|the\s+first(?:\s+one)?|(?:\d+|two|three|four|five|six|"
    r"seven|eight)(?=\s*(?:x|by|cubes?\s+high|cubes?\s+tall|high|tall|long)\b)|(?:the|an?)\s+(?:\3\s+of\s+)?(?=(?:\d+|two|three|four|five|six|seven|eight)\s+(?:on|at|in|to)\s))"
    r"\s*(?:[^.;]|(?<=\d)\.(?=\d))*)",
    re.IGNORECASE,
)


_OTHER_SIDE = re.compile(
    r"\b(in\s+front\s+of|behind|to\s+the\s+left\s+of|to\s+the\s+right\s+of|left\s+of|right\s+of)"
    r"\s+the\s+([a-z]+)\s*,?\s+and\s+((?:then\s+)?(?:an?|another|one|the\s+other)\b[^.;]{0,40}?)"
    r"\b(in\s+front\s+of|behind|to\s+the\s+left\s+of|to\s+the\s+right\s+of|left\s+of|right\s+of)"
    r"\s+(it|the\s+\2)\b",
    re.IGNORECASE,
)
"""'a tower in front of the wall and a tower behind it': it is the wall, on its other side
(and 'the wall and a tower' is no phrase of one wall more and a tower)."""


def _side_word(relation: str) -> str:
    """The side a relation names ("in front of" → front, "to the left of" → left)."""
    said = relation.lower()
    return next((w for w in ("front", "left", "right") if w in said), "back")


def _other_side(m: re.Match[str]) -> str:
    if m.group(2).lower() not in lx.SHAPE_WORDS or _side_word(m.group(1)) != lx.OPPOSITE_SIDE.get(
        _side_word(m.group(4))
    ):
        return m.group(0)
    return f"{m.group(1)} the {m.group(2)}; and {m.group(3)}{m.group(4)} the {m.group(2)}"


# "a single cube in each of the four corners of the table": one in each corner region
_CORNERS = re.compile(
    r"(?:^|(?<=[,.;:]\s)|(?<=\band\s)|(?<=\bthen\s))\s*(?:(?:now|next|so|ok)\s*,?\s+)?"
    # "Now it will place one cube in each of the four corners": who places it, said first
    r"(?:(?:it|the\s+robot|we|you|i)\s+(?:will|should|must|can|could|(?:is|are|am)\s+going\s+to)\s+)?"
    r"(?:(?:please\s+)?(?:put|place|stick|set|build|"
    r"make|stand|pop|add)\s+)?((?:(?:an?|one|a\s+single|single)\s+)?"
    r"(?:\S+\s+){0,3}?(?:cube|block|brick|tower|stack|column|pyramid|pad|slab)s?"
    r"(?:\s+(?:of\s+)?(?:\d+|two|three|four|five|six|seven|eight|nine|ten)(?:\s+(?:cubes?|high|tall|"
    r"levels?))?)?)\s+"
    r"(?:in|at|on|into)\s+(?:each|every|all)\s+"
    r"(?:one\s+)?(?:of\s+)?(?:the\s+)?(?:four\s+|4\s+)?corners?"
    r"(\s+of\s+the\s+(?:table|workspace|work\s*space|cell|work\s*area|area))?",
    re.IGNORECASE,
)


_COMPARISON = re.compile(
    r"\b(?:taller|shorter|higher|lower|bigger|smaller|wider|narrower|longer|larger|thicker|"
    r"deeper|more|fewer|less)\s+(?:\w+\s+)?than\s+(?:the\s+|that\s+|those\s+|a\s+)?\w+",
    re.IGNORECASE,
)


_BY_HOW_MUCH = re.compile(
    r"\b(?:\d+|two|three|four|five|six)\s+(?:cubes?|parts?|blocks?|levels?|layers?)?\s*$",
    re.IGNORECASE,
)


_LOOSE_CUBES = re.compile(
    r"(?<!\bof\s)(?<!\bwith\s)(?<!\bfrom\s)(?<!\beach\s)"  # "towers of 4 cubes, one …": their size
    r"\b(two|three|four|2|3|4)\s+(?:single\s+|loose\s+|separate\s+)?(?:cubes|bricks)\s*,\s*"
    r"(?=one\b(?!\s+(?:layer|level|course|high|tall|thick|deep)\b))",
    re.IGNORECASE,
)
"""'two cubes, one in the back left corner and one …': structures of one part each."""
_BY_IT = (
    r"(?:right\s+|just\s+)?(?:next\s+to|beside|behind|in\s+front\s+of|on\s+top\s+of|"
    r"(?:to\s+the\s+)?(?:left|right)\s+of)\s+(?:it|that)\s*,?\s*"
)
_ONE_OF = re.compile(
    r"(\bthen\s+|\band\s+|,\s*)(" + _BY_IT + r")?one\s+(?:(of|with)\s+(?=(?:\d|" + _NUMBER_WORD
    + r")\b)|(?=(?:\d+|" + _NUMBER_WORD + r")\s+(?:cubes?\s+)?(?:high|tall|long)\b)"
    r"|(?=(?:twice|double|thrice|half|just|exactly|equally)\s+as\s+(?:tall|high|long|big)\b))",
    re.IGNORECASE,
)
"""'a tower of 2, then one of 3', 'and next to it one 6 high': another of the structure named
before."""


def _one_of(m: re.Match[str]) -> str:
    """ "One tower of six cubes and one of four": another one; "two towers, one of 3 and one
    of 5" names the ones counted before, not more."""
    sentence = re.split(r"[.;!?]", m.string[: m.start()])[-1].lower()
    named = [w for w in re.findall(r"[a-z]+", sentence) if w in lx.SHAPE_WORDS]
    if m.group(1).strip() != "then" and named and named[-1].endswith("s"):
        return m.group(0)
    return f"{m.group(1)}{m.group(2) or ''}another one {m.group(3) or ''} "


_FLOORS = re.compile(r"\b(\d+|" + "|".join(NUMBER_WORDS) + r")\s+(floors?)\b", re.I)


def _floors_as_levels(text: str, st: ReadState) -> str:
    """ "a pyramid of three floors": the levels of the structure named before in the sentence
    (a floor is a structure of its own only where nothing else is named: "two floors of 3x3")."""

    def levels(m: re.Match[str]) -> str:
        sentence = re.split(r"[.;!?]", text[: m.start()])[-1]
        if re.search(r"(?:\bby|\bx|[×*])\s*$", sentence, re.I):  # "a 3 by 3 floor": a size
            return m.group(0)
        named = [lx.SHAPE_WORDS.get(w) for w in re.findall(r"[a-z]+", sentence.lower())]
        shape = next((s for s in reversed(named) if s), None)
        if shape is None or shape in ("grid", "block"):
            return m.group(0)
        st.notes.append(f"read '{m.group(0)}' as {m.group(1)} levels of the {shape}")
        return f"{m.group(1)} levels"

    return _FLOORS.sub(levels, text)


_PLURAL_THEN_COUNT = re.compile(
    r"(?:^|(?<=[.;:!?]\s)|(?<=[.;:!?]))\s*([^.;:!?,]*?\b([a-z]+)s\b[^.;:!?,]*),\s*"
    r"(two|three|four|five|six|[2-9])\s+of\s+them\b",
    re.IGNORECASE,
)


def _count_of_plural(text: str, st: ReadState) -> str:
    """ "Towers of four, three of them", "4-high pillars, two of them": that many of them (the
    count said after the plural that names them)."""

    def counted(m: re.Match[str]) -> str:
        first = re.match(r"(\w+)(-?)", m.group(1).strip().lower())  # "4-high" is no count
        noun = m.group(2).lower()
        if (
            noun not in lx.SHAPE_WORDS
            or noun in lx.SELDOM_STRUCTURES
            or (first and not first.group(2) and (first[1].isdigit() or first[1] in NUMBER_WORDS))
        ):
            return m.group(0)
        st.notes.append(f"read '{m.group(0).strip()}' as {m.group(3)} {noun}s")
        return f" {m.group(3)} {m.group(1).strip()}"

    return _PLURAL_THEN_COUNT.sub(counted, text)


_COUNTED_SINGULAR = re.compile(
    r"(?<!\ba\s)(?<!\ban\s)(?<!\bthe\s)(?<!\bone\s)(?<!\bthat\s)(?<!\bthis\s)"
    r"\b([2-9]|1[0-2]|two|three|four|five|six|seven|eight|nine|ten)\s+([a-z]+)\b(?!-)"
    r"(?=\s*,?\s*(?:of|with)\s+(?:\d|one|two|three|four|five|six|seven|eight|nine|ten)\b|"
    r"\s*,\s*(?:(?:long|high|tall|wide)\s+\d|\d+\s+(?:long|high|tall|wide|cubes?)\b)|"
    # "two pyramid next each other": a relation only several have
    r"\s+(?:(?:next\s+(?:to\s+)?|beside\s+|by\s+|near\s+)?each\s+other|side\s+by\s+side|"
    r"in\s+a\s+(?:row|line))\b)",
    re.IGNORECASE,
)


def _counted_singular(text: str, st: ReadState) -> str:
    """ "I want 3 tower of 3 cube", "make 2 wall, long 4": a count before a structure's singular
    name, its size said after it, is that many of them (not a tower 3 high)."""

    def counted(m: re.Match[str]) -> str:
        noun = m.group(2).lower()
        if lx.SHAPE_WORDS.get(noun) is None or noun in lx.SELDOM_STRUCTURES or noun.endswith("s"):
            return m.group(0)
        if re.search(r"(?:\bx|\bby|[*×]|\d)\s*$", m.string[: m.start()], re.I):
            return m.group(0)  # "a 2 x 2 block, 2 high": the last of a size group
        plural = noun + ("es" if noun.endswith(("ch", "sh", "x")) else "s")
        st.notes.append(f"read '{m.group(0)}' as {m.group(1)} {plural}")
        return f"{m.group(1)} {plural}"

    return _COUNTED_SINGULAR.sub(counted, text)


_ONE = (
    r"(?:a|an)\s+(?!(?:same|other|second|new|first|last|next|different|single)\b)([a-z]+)\s+one\b"
    r"(?!\s+(?:cubes?|parts?|blocks?|bricks?|high|tall|long|wide|deep|thick|layers?|levels?)\b)"
)
_WANTERS = frozenset({"i", "we", "you", "they", "d", "would", "should", "do", "really", "id"})
_SIZED_ONE = (
    r"(big|small|little|large|huge|tiny|tall|short|low|long|wide|narrow|giant|medium)\s+one\b"
    r"(?!\s+(?:cubes?|parts?|blocks?|bricks?|high|tall|long|wide|deep|thick|layers?|levels?)\b)"
)
"""'big one' with no article, as operators type it."""
_APPOSED_LIST = re.compile(
    r"(?<=,)\s*"
    + _ONE
    + r"((?:\s*(?:,|and|,\s*and)\s*"
    + _ONE.replace("([a-z]+)", "[a-z]+")
    + r")+)"
    + r"|(?<=,)\s*"
    + _SIZED_ONE
    + r"((?:\s*(?:,|and|,\s*and)\s*"
    + _SIZED_ONE.replace("(big|", "(?:big|")
    + r")+)",
    re.IGNORECASE,
)
_APPOSED = re.compile(
    r"(?<=,)\s*(?:" + _ONE + r"|" + _SIZED_ONE + r")"
    r"(?!\s+(?:of|with|that|which|on|at|in|to|next|behind|beside|and|cubes?|parts?|high|tall|"
    r"long)\b)",
    re.IGNORECASE,
)
"""'two towers, a big one and a small one': one of each; 'a fence, a square one': the
structure named before, described again."""
_CLOSED = frozenset({"square", "rectangular", "closed", "round", "circular"})
_CLOSED_WALL = re.compile(
    r"\b(square|rectangular|closed|round|circular)\s+(?:fence|wall|border|barrier)(s?)\b", re.I
)
_LIKE_A = re.compile(
    r"(?:,\s*|\s+)\b(?:just\s+|sort\s+of\s+|a\s+bit\s+)?(?:like|resembling|similar\s+to|"
    r"looking\s+like|in\s+the\s+style\s+of|(?:it\s+|that\s+|so\s+(?:it|that\s+it)\s+)?"
    r"(?:should|will|would|ought\s+to)\s+(?:come\s+out|end\s+up|turn\s+out|look)\s+(?:as|like)|"
    r"(?:expected|end|final)(?:\s+(?:result|outcome|shape))?\s*(?:should\s+be|will\s+be|is)?\s*:|"
    r"(?:the\s+)?(?:result|outcome)\s*(?:should\s+be|will\s+be|is)?\s*:|"
    # "Two rows of four, one on top of the other. That's a small wall.": what they make
    r"(?<=[.;!?,]\s)(?:so\s+)?(?:that'?s|that\s+is|which\s+is|(?:which|that|this)\s+makes)|"
    # "… a beam across the tops to make a gate", "… so it makes a box": what the parts make
    r"(?:in\s+order\s+)?to\s+(?:make|form|create)|so\s+(?:that\s+)?(?:it|they|the\s+whole\s+"
    r"thing)\s+(?:makes?|forms?|becomes?))"
    r"\s+(?:a|an|one)\s+[^,.;:!?]*"
    # a user story's "Done when: one row, seven long.": the whole sentence describes the result
    r"|(?:,\s*|\s+)\b(?:(?:done|complete|finished|accepted)\s+when|acceptance(?:\s+criteria)?|"
    r"definition\s+of\s+done)\s*:\s+(?:a|an|one)\s+[^.;:!?\n]*",
    re.IGNORECASE,
)


_RESULT = re.compile(
    r"\b(?:come\s+out|end\s+up|turn\s+out|expected|result|outcome|final|end|done|complete|"
    r"finished|accepted|acceptance)\b",
    re.IGNORECASE,
)


_RESTATED = re.compile(
    r"\b(an?)\s+([a-z]+)((?:\s+(?:down|first|in\s+the\s+middle|here))*)\s*,\s*"
    r"(an?\s+(?=[^,.;]*\d)[^,.;]*?)\s*(?=,|[.;]|$)",
    re.IGNORECASE,
)
"""A structure named bare, then again with its size after a comma: the same one."""


def _described_again(text: str, st: ReadState) -> str:
    """Apposition and likeness: 'a fence, a square one' is that fence, square; 'two towers, a
    big one and a small one' one of each; 'a block 2 by 3, like a little tower house' the
    block, the likeness a description (with a structure named before it)."""

    def listed(m: re.Match[str]) -> str:
        words = re.findall(r"\b([a-z]+)\s+one\b", m.group(0), re.IGNORECASE)
        return " " + " and ".join(f"one {w}" for w in words) + " "

    text = _APPOSED_LIST.sub(listed, text)

    def restated(m: re.Match[str]) -> str:
        nouns = [w for w in re.findall(r"[a-z]+", m.group(4).lower()) if w in lx.SHAPE_WORDS]
        first = lx.SHAPE_WORDS.get(m.group(2).lower())
        if first is None or re.search(r"\b(?:and|or|then)\b", m.group(4)):
            return m.group(0)  # "a tower, a tower of 3 and a wall": a list
        one = re.match(r"an?\s+(?:(\w+)\s+)?one\b(?!\s+(?:cube|block|part|level|layer)s?\b)(.*)",
                       m.group(4), re.IGNORECASE)  # fmt: skip
        if not nouns and one:  # "a wall, a long one of 6 cubes" (a column of 6 was built)
            st.notes.append(f"read '{m.group(0).strip(' ,')}' as one {m.group(2).lower()}")
            return f" a {one.group(1) or ''} {m.group(2)}{one.group(2)}{m.group(3)} "
        if len(nouns) != 1:
            return m.group(0)
        second = lx.SHAPE_WORDS[nouns[0]]
        if not (first == second or {first, second} <= {"block", "grid"}):
            return m.group(0)
        st.notes.append(f"read '{m.group(0).strip(' ,')}' as one {nouns[0]}")
        return f" {m.group(4)}{m.group(3)} "

    # "Put a plinth down first, a 3 by 3 slab one cube thick, and …": the plinth said again
    # with its size (a plinth of the default size was built beside the slab)
    text = _RESTATED.sub(restated, text)

    def again(m: re.Match[str]) -> str:
        adjective = (m.group(1) or m.group(2)).lower()  # "a big one", "big one"
        if adjective in NUMBER_WORDS or (adjective in lx.SHAPE_WORDS and adjective not in _CLOSED):
            return m.group(0)
        st.notes.append(f"read '{m.group(0).strip()}' as the structure named before it")
        return f" {adjective} " if adjective not in _CLOSED else f" , {adjective}-closed , "

    text = _APPOSED.sub(again, text)
    # "a fence, a square one": the fence closed, as a ring
    text = re.sub(r"\b(fence|wall|border|barrier)(s?)\b([^.;]*?)\s*,\s*(\w+)-closed\s*,",
                  r"\4 ring\2\3 ,", text, flags=re.IGNORECASE)  # fmt: skip
    text = _CLOSED_WALL.sub(lambda m: f"{m.group(1)} ring{m.group(2)}", text)

    def likeness(m: re.Match[str]) -> str:
        before = re.findall(r"[a-z]+", text[: m.start()].lower())
        if before and before[-1] in _WANTERS and not m.group(0).lstrip().startswith(","):
            return m.group(0)  # "I'd like a pyramid": the verb
        purpose = _MADE.match(m.group(0))
        if purpose and ((before and before[-1] in _PURPOSE_LED) or _WAY.search(m.group(0))):
            # "then I want to make a wall": what is wanted; "to form a corridor leading away
            # from me": which way the structures run, read by what reads ways
            return m.group(0)
        if not any(w in lx.SHAPE_WORDS for w in before):
            return m.group(0)  # "something like a park bench": the likeness is all there is
        said = m.group(0).strip(" ,")
        if _WHAT_IT_MAKES.match(said) and re.search(rf"\d|\b{_N}\b", said, re.IGNORECASE):
            return m.group(0)  # "… that's a tower of 5": a size, not a name for it
        if _RESULT.search(said) or purpose:  # "Expected result: a 2 x 3 x 2 block", "… so it
            # becomes a solid plate", "… to make a gate": what it makes, checked at the end
            st.claims.append(("result", said))
            return " "
        size = _LIKENESS_SIZE.search(said)
        if size is not None:  # "a flat square like a floor six by six": the size is the square's
            st.notes.append(f"read '{said[: size.start()].strip()}' as a description, not a "
                            f"structure, and '{size.group(0)}' as the size")  # fmt: skip
            return f" , {size.group(0)} "
        st.notes.append(f"read '{said}' as a description, not a structure")
        return " "

    text = _LIKE_A.sub(likeness, text)

    def likeness_named(m: re.Match[str]) -> str:
        if families_said(m.group(0)) or re.search(r"\d", m.group(0)):
            return m.group(0)  # "like the other tower", "like stairs": a family, read as said
        return likeness(m)

    text = _LIKE_THE.sub(likeness_named, text)

    def leading(m: re.Match[str]) -> str:
        rest = re.split(r"[.;!?](?:\s|$)", text[m.end() :])[0]
        if not any(w in lx.SHAPE_WORDS for w in re.findall(r"[a-z]+", rest.lower())):
            return m.group(0)  # "Like a T formation: bar of 3, stem of 3": the likeness names it
        st.notes.append(f"read '{m.group(0).strip(' :')}' as a description, not a structure")
        return " "

    return _LEADING_LIKE.sub(leading, text)


_LIKE_THE = re.compile(
    r"(?:,\s*|\s+)\b(?:just\s+|sort\s+of\s+|a\s+bit\s+)?like\s+(?:(?:the|those|these)\s+"
    r"(?!(?:first|second|third|other|last|previous|same|one|ones|left|right|front|back|middle|"
    r"tallest|biggest|smallest|shortest|longest)\b)[^,.;:!?]*|(?:[a-z]+\s+){0,2}[a-z]+s\b"
    r"(?:\s+lined\s+up)?(?=\s*[,.;:!?]))",
    re.IGNORECASE,
)
"""'a big L like the letter magnet on the fridge', 'two towers like twin teddy bears': a
likeness with no size in it, after the structure it describes."""
_LEADING_LIKE = re.compile(
    r"(?:^|(?<=[.;!?]\s))\s*(?:(?:make|build)\s+(?:it|something)\s+(?:that\s+)?|it\s+should\s+)?"
    r"(?:(?:looks?|looking|shaped|styled)\s+)?(?:just\s+|a\s+bit\s+|sort\s+of\s+|kind\s+of\s+)?"
    r"like\s+[^:,.;!?\d]{2,60}?\s*(?::|,(?=\s*(?:an?|one)\s+[a-z]+\s*(?:[.;!?]|$)))\s*",
    re.IGNORECASE,
)
"""'Like a city skyline: three towers …', 'Like a podium: a 3x3 block …': a likeness said
first, the structure described after the colon."""


_N = r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
_MADE = re.compile(
    r"\s*,?\s*(?:(?:in\s+order\s+)?to\s|so\s+(?:that\s+)?(?:it|they|the\s+whole\s+thing)\s)",
    re.IGNORECASE,
)
_WAY = re.compile(
    r"\b(?:away|towards?|front|back|left|right|along|across|leading|running|facing)\b",
    re.IGNORECASE,
)
_PURPOSE_LED = frozenset({"want", "wants", "need", "needs", "like", "love", "going", "have", "has",
                          "able", "try", "how", "please", "also", "then", "and", "now", "next",
                          "asked", "ask", "wish", "hope", "plan", "be", "is", "are", "robot"})
"""Words before "to make a …" that make it a structure asked for, not what the parts make."""
_WHAT_IT_MAKES = re.compile(
    r"(?:so\s+)?(?:that'?s|that\s+is|which\s+is|(?:which|that|this)\s+makes)\b", re.IGNORECASE
)
_LIKENESS_SIZE = re.compile(rf"\b{_N}\s*(?:x|by)\s*{_N}(?:\s*(?:x|by)\s*{_N})?\b", re.IGNORECASE)
"""A size said inside a likeness ("like a floor six by six")."""

_A_SIZE = (
    r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+(?:cubes?\s+)?(?:high|tall|long|"
    r"levels|layers|steps|tiers)\b"
)
_SIZE_AFTER_IT = re.compile(
    r"\b(next\s+to|beside|behind|in\s+front\s+of|to\s+the\s+(?:left|right)\s+of|on\s+top\s+of|on)\s+"
    r"(it|them)\s*,?\s+"
    r"(" + _A_SIZE + r"(?:\s*,?\s*(?:and\s+)?" + _A_SIZE + r")*)"
    r"(?=\s*(?:[.;,]|$))",
    re.IGNORECASE,
)
"""A size said after the pronoun of a relation is the subject's ("… next to it, 2 high", "… next
to it, 5 high, 4 long")."""

_TOUCHING_IT = re.compile(
    r"\b(it|them)\s*,?\s*(?:and\s+)?touching\s+(?:it|them|each\s+other)\b", re.IGNORECASE
)
"""'a wall next to it, touching it': the same one, said again (the relation's object was read
as 'it, touching it': no structure)."""

_LEVEL_LABEL = re.compile(
    r"(?:^|(?<=[.;:,!\n]))\s*(?:level|layer|tier|floor|storey|story|lvl)\s*"
    r"(\d+|one|two|three|four|five|six|seven|eight|nine|ten)(?:\s*[:=)-]|\s+(?:is|has)\b|"
    r"(?=\s+(?:(?:an?|one|two|three|four|five|six|just|only|single)\s|\d|the\s+same\b)))\s*",
    # "level 1 is a 4x2 slab", "layer one 2 by 6", "level 3 one cube"
    re.IGNORECASE,
)


_LEVEL_WORD = re.compile(
    r"(?:^|(?<=[.;:,!\n])|(?<=\band\s))\s*(?:the\s+)?(bottom|base|lowest|ground|first|1st|second|"
    r"2nd|middle|third|3rd|fourth|4th|top|upper|last)(?:(?:\s+(?:level|layer|tier|floor|storey|"
    r"course))(?:\s+(?:is|has)\s+|\s*[:=-]\s*|\s+(?=(?:an?|one|just|only|\d)\b))|\s*[:=-]\s*|"
    r"(?<=top)\s+(?=(?:an?\s+single|one|just|only|a\s+1-cube)\b)|\s+(?=\d+\s*(?:x|by)\s*\d))",
    re.IGNORECASE,
)
_LEVEL_RANK = {"bottom": 1, "base": 1, "lowest": 1, "ground": 1, "first": 1, "1st": 1, "second": 2,
               "2nd": 2, "middle": 2, "third": 3, "3rd": 3, "fourth": 4, "4th": 4, "top": 99,
               "upper": 99, "last": 99}  # fmt: skip
"""'Bottom: a 3 by 3 square. Middle: 2 by 2. Top: one cube.': levels named in words."""


_SAME_LEVEL = re.compile(
    r"\s*(?:(?:just\s+)?(?:the\s+)?same(?:\s+again|\s+as\s+(?:the\s+)?(?:one\s+|level\s+|layer\s+)?"
    r"(?:below|before|under\s+it|first))?|ditto|again)\s*",
    re.IGNORECASE,
)


_LEVEL_GRID = re.compile(
    rf"(?:an?\s+)?({_N})\s*(?:x|by)\s*({_N})(?:\s+(?:square|slab|layer|patch|grid|plate|area))?"
    r"(?!\s*(?:x|by)\b)",
    re.IGNORECASE,
)
_LEVEL_ROW = re.compile(
    rf"(?:an?\s+)?({_N})\s+cubes?\s+(?:in\s+a\s+(?:line|row)|(?:long|wide|across)\b)",
    re.IGNORECASE,
)
_LEVEL_BARE = re.compile(
    rf"(?:a\s+single|just\s+one|only\s+one|one\s+single|({_N}))(?:\s+cubes?)?"
    r"(?=\s*(?:$|,|on\s|in\s+the\s+(?:middle|centre|center)|cent(?:red|ered)))",
    re.IGNORECASE,
)


_NUMBERED_LEVEL = re.compile(r"\s*\(\s*([1-9])\s*\)\s*")


_LEVELLED_NOUN = r"(?:(?:stepped|step|tiered|layered)\s+)?(?:pyramid|ziggurat|(?:wedding\s+)?cake)"
"""A structure that is its levels: a pyramid, a ziggurat, a (wedding) cake."""
_LEVEL_SIZE = rf"{_N}\s*(?:x|by|×)\s*{_N}"
_LEVELS_SAID = (
    r"(?:(?:its|the)\s+)?(?:(?P<count>" + _N + r")\s+)?(?:levels|layers|tiers)\b"
    r"(?:\s*[:,=]|\s+(?:are|of))?\s*"
)
_LEVEL_LIST = re.compile(
    r"(?P<lead>\b(?:(?:a|an|the)\s+)?(?:(?P<counted>" + _N + r")[- ](?:levels?|layers?|tiers?|"
    r"steps?)\s+)?" + _LEVELLED_NOUN + r"\b"
    r"(?:\s*[,:]\s*|\s+(?:with|of|in)\s+|\s+)(?:" + _LEVELS_SAID + r")?|\b"
    + _LEVELS_SAID.replace("count", "alone") + r")"
    r"(?P<sizes>" + _LEVEL_SIZE + r"(?:\s*[,;]?\s*(?:and\s+then\s+|and\s+|then\s+)?"
    + _LEVEL_SIZE + r")+)"
    r"(?P<top>\s*[,;]?\s*(?:and\s+then\s+|and\s+|then\s+)?(?:a\s+single|one|a|1)\s+cube"
    r"(?:\s+on\s+top)?\b)?(?!\s*(?:x|by|×)\b)",
    re.IGNORECASE,
)
"""'a pyramid with levels 5x5, 3x3 and 1x1', 'a stepped pyramid: 5 by 5, then 3 by 3': the
levels listed bottom up."""


def _level_list(text: str, st: ReadState) -> str:
    """A pyramid (or levels) listed by their sizes, each no larger than the one under it: the
    levels labelled in order, for `_level_labels` (the pyramid is those levels, not another)."""
    m = _LEVEL_LIST.search(text)
    if m is None:
        return text
    sizes = [
        [int(words_to_numbers([n.lower()])[0]) for n in re.findall(_N, size, re.IGNORECASE)]
        for size in re.findall(_LEVEL_SIZE, m.group("sizes"), re.IGNORECASE)
    ]
    if m.group("top"):
        sizes.append([1, 1])
    if any(b[0] * b[1] > a[0] * a[1] or min(b) > min(a) for a, b in itertools.pairwise(sizes)):
        return text  # a level larger than the one it would stand on: not listed bottom up
    counted = m.group("counted") or m.group("count") or m.group("alone")
    if counted and int(words_to_numbers([counted.lower()])[0]) != len(sizes):
        return text  # "a 4-level pyramid 3x3, 2x2": the count and the list disagree
    labels = " ".join(f"({k}) {a} by {b}" for k, (a, b) in enumerate(sizes, 1))
    st.notes.append(f"read '{m.group(0).strip()}' as its levels, bottom up")
    return f"{text[: m.start()]} levels: {labels}. {text[m.end() :]}"


def _level_named(said: str, prev: str) -> str:
    """A level said by its size alone names what it is: "2x2" a 2 by 2 slab, "5 cubes in a
    line" a row of 5, "3" after a row a row of 3, "a single cube" a 1-cube tower."""
    if m := _LEVEL_GRID.match(said):
        return f"a {m.group(1)} by {m.group(2)} slab{said[m.end() :]}"
    if m := _LEVEL_ROW.match(said):
        return f"a row of {m.group(1)}{said[m.end() :]}"
    m = _LEVEL_BARE.match(said)
    if m is None:
        return said
    count = int(words_to_numbers([m.group(1).lower()])[0]) if m.group(1) else 1
    if count == 1:
        return f"a 1-cube tower{said[m.end() :]}"
    if re.match(r"a\s+row\s+of\b", prev, re.IGNORECASE):
        return f"a row of {count}{said[m.end() :]}"  # "5 cubes in a line, … 3 on top": a row
    return said


_LEVELLED = re.compile(
    r"(?:(?:a|an|the)\s+)?" + _LEVELLED_NOUN
    + r"\s*(?:(?:with|of|in)\s+(?:(?:its|the)\s+)?)?(?:(?:levels|layers|tiers)\b)?"
    r"\s*[:,.-]?\s*$",
    re.IGNORECASE,
)
"""A pyramid named with no size of its own just before its levels are labelled."""


def _level_labels(text: str, st: ReadState) -> str:
    """ "level 1: 4x4 floor. level 2: 3x3 on top. level 3: 2x2.": each level labelled after
    the first stands on the one before it (also named in words: "Bottom: … Middle: … Top:")."""
    labels = list(_LEVEL_LABEL.finditer(text))
    numbers = [int(words_to_numbers([m.group(1).lower()])[0]) for m in labels]
    first = [w for w in _LEVEL_WORD.finditer(text[: labels[0].start()])] if labels else []
    if numbers[:1] == [2] and first and _LEVEL_RANK[first[-1].group(1).lower()] == 1:
        labels, numbers = [first[-1], *labels], [1, *numbers]  # "bottom level: 3 by 3. level 2: …"
    if len(labels) < 2 and re.search(r"\b(?:levels|layers|tiers)\b", text, re.IGNORECASE):
        labels = list(_NUMBERED_LEVEL.finditer(text))  # "levels: (1) a 5x5 slab (2) …"
        numbers = [int(m.group(1)) for m in labels]
    if len(labels) < 2:
        labels = list(_LEVEL_WORD.finditer(text))
        numbers = [_LEVEL_RANK[m.group(1).lower()] for m in labels]
        if len(labels) >= 2 and numbers[-1] == 99:
            numbers[-1] = numbers[-2] + 1 if len(numbers) > 1 else 2  # "top": the last one
    if len(labels) < 2 or numbers != list(range(numbers[0], numbers[0] + len(numbers))):
        return text
    out = [text[: labels[0].start()]]
    if named := _LEVELLED.search(out[0]):  # "a pyramid: bottom level 5x5, …": those levels
        st.notes.append(f"read '{named.group(0).strip(' :,-')}' as the levels labelled")
        out[0] = out[0][: named.start()] + " "
    prev = ""
    for i, m in enumerate(labels):
        end = labels[i + 1].start() if i + 1 < len(labels) else len(text)
        segment = text[m.end() : end].strip()
        said = re.match(r"[^.;!?]*", segment).group(0).rstrip(" ,")  # type: ignore[union-attr]
        said = re.sub(r"^(?:just|only)?\s*(?:the\s+)?(?:middle|centre|center|one)\s+cube\b",
                      "one cube", said, flags=re.IGNORECASE)  # "just the middle cube": one
        rest = segment[len(said) :].lstrip(".;!? ")
        if i and _SAME_LEVEL.fullmatch(said):
            said = prev  # "layer one 2 by 6, layer two the same": that level again
        said = _level_named(said, prev)
        prev = re.sub(r"\s+on\s+top\b.*$", "", said, flags=re.IGNORECASE)
        # "second level a 2x2 patch, and a single cube on top": the on top is the cube's
        head = re.split(r"\s*,\s*|\s+and\s+", said, maxsplit=1)[0]
        if i and not re.search(
            r"\bon\s+(?:top|it|that|(?:one|each|either|both|all|the)\s+(?:\w+\s+)?(?:corner|end)s?)\b",
            head,
            re.IGNORECASE,
        ):  # "level 4: 1 cube on one corner": on the one before, at a corner
            said = f"{head} on top{said[len(head) :]}"
        out.append(f" then {said}. {rest}" if i else f" {said}. {rest}")
    st.notes.append("read the levels labelled in order as each on top of the one before")
    return "".join(out)


_PIECE = re.compile(
    r"\b(?:(a|an|one|two|three|four|\d+)\s+)?(?:tetris\s+|tetromino\s+)?"
    r"(?:(?<![a-z])([LTIOJ])[- ]?(?:pieces?|tetrominos?|tetrominoes|blocks?)|"
    r"(?:tetris|tetromino)\s+(?:pieces?|shapes?|blocks?)(?:\s*,?\s*any\s+one)?)\b"
    r"((?:\s*,?\s*(?:standing|stood|set|placed))?\s+(?:on\s+(?:its\s+|their\s+)?end|upright|"
    r"vertical(?:ly)?))?",
    re.IGNORECASE,
)
_LIKE_PIECE = re.compile(
    r"\s*[-—–,]?\s*\blike\s+(?:the|a|an)\s+(?:tetris\s+|tetromino\s+)?(?:[LTIOJ][- ]?(?:pieces?|"
    r"tetrominos?|blocks?)|(?:tetris|tetromino)\s+(?:pieces?|shapes?|blocks?))\b",
    re.IGNORECASE,
)
_PIECES = {
    "I": ("row of 4", "rows of 4"), "O": ("2 by 2 slab", "2 by 2 slabs"),
    "L": ("L shape 3 by 2", "L shapes 3 by 2"), "J": ("L shape 3 by 2", "L shapes 3 by 2"),
    "T": ("T shape 3 by 2", "T shapes 3 by 2"),
}  # fmt: skip


def _tetris(text: str, st: ReadState) -> str:
    """ "a Tetris L-piece", "an O-piece", "two I-pieces on end": the four-cube pieces as the
    families that build them (S and Z have none: left for the reading to report)."""

    def likeness(m: re.Match[str]) -> str:
        if not families_said(m.string[: m.start()]):
            return m.group(0)
        st.notes.append(f"read '{m.group(0).strip(' ,-—–')}' as what the structure named before "
                        "looks like")  # fmt: skip
        return " "

    # "an L shape, one arm four and the other three - like the tetris piece": no second one
    text = _LIKE_PIECE.sub(likeness, text)

    def piece(m: re.Match[str]) -> str:
        count = (m.group(1) or "a").lower()
        letter = (m.group(2) or "L").upper()
        if letter not in _PIECES:
            return m.group(0)
        many = count not in ("a", "an", "one")
        what = _PIECES[letter][1 if many else 0]
        if letter == "I" and m.group(3):  # stood on end: a column
            what = "towers of 4" if many else "tower of 4"
        article = "an" if what.startswith(("L", "I")) and not many else "a"
        said = f"{count if many else article} {what}"
        st.notes.append(f"read '{m.group(0).strip()}' as {said}")
        return f" {said} "

    return _PIECE.sub(piece, text)


_ON_END = re.compile(
    r"\b(a|one)\s+row\s+of\s+(\d+|" + _NUMBER_WORD + r")(?:\s+cubes?)?\s*,?\s*"
    r"(?:standing\s+|stood\s+|set\s+|placed\s+)?(?:on\s+(?:its\s+)?end|upright|vertical(?:ly)?)\b",
    re.IGNORECASE,
)


_ORDINAL_PLACES = re.compile(
    r"(\b(?:two|three|four|[2-4])\s+(?:[\w-]+\s+){0,2}?([a-z]+)s\b[^.;!?]*?)\s*[.;!]\s*"
    r"(?:(?:then\s+|now\s+)?(?:put|place|set|position|stand|have|make)\s+)?"
    r"(?=the\s+first(?:\s+one)?\s+(?:goes\s+|stands\s+|is\s+)?(?:on|at|in|to|behind|beside|next|"
    r"near|by|against)\b[^.;!?]*\bthe\s+(?:second|other|last)\b)",
    re.IGNORECASE,
)
"""'Build two towers of 3. Put the first one on the left and the second one on the right.': the
places of the ones just counted, in order."""


def _ordinal_places(m: re.Match[str]) -> str:
    if m.group(2).lower() not in lx.SHAPE_WORDS:
        return m.group(0)
    return f"{m.group(1)}, "


_PART_NOUNS = frozenset({"leg", "legs", "pillar", "pillars", "post", "posts", "step", "steps",
                         "arm", "arms", "level", "levels", "layer", "layers"})  # fmt: skip
_PLACE = (
    r"(?:on|at|in|to)\s+the\s+(?:far\s+)?(?:left|right|front|back|middle|centre|center)"
    r"(?:\s+(?:left|right))?(?:\s+(?:side|corner|end|half))?"
)
_STANDS = r"(?:goes\s+|is\s+|stands\s+|sits\s+)?"
_PAIR_PLACES = re.compile(
    r"(\ban?\s[^.;,]*?)\s+and\s+(an?\s[^.;,]*?)\s*[.;,]\s*(?:(?:then\s+)?(?:put|place|set)\s+)?"
    r"the\s+first(?:\s+one)?\s+" + _STANDS + r"(" + _PLACE + r")\s*,?\s*(?:and\s+)?"
    r"the\s+(?:second|other)(?:\s+one)?\s+" + _STANDS + r"(" + _PLACE + r")",
    re.IGNORECASE,
)
"""'a 3-level pyramid and a 2-level one; the first one goes on the left, the second one on the
right': each of the two named its place."""


def _pair_places(m: re.Match[str]) -> str:
    named = [w for w in re.findall(r"[a-z]+", f"{m.group(1)} {m.group(2)}".lower())
             if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES]  # fmt: skip
    if len(named) != 2:
        return m.group(0)
    return f"{m.group(1)} {m.group(3)} and {m.group(2)} {m.group(4)}"


_FORMER_LATTER = re.compile(
    r"\bthe\s+(former|latter)(?:\s+one)?\b|\bthe\s+(shorter|taller|smaller|bigger|larger|longer|"
    r"higher|lower|wider|narrower)\s+of\s+the\s+two\b",
    re.IGNORECASE,
)


def _former_latter(text: str, st: ReadState) -> str:
    """ "a ring and a tower; put the latter inside the former": the second and the first of
    the two named before; "the shorter of the two": the shorter one."""

    def which(m: re.Match[str]) -> str:
        if m.group(2):
            return f"the {m.group(2)} one"
        words = re.findall(r"[a-z]+|\d+", text[: m.start()].lower())
        named = [
            w for k, w in enumerate(words)
            if w in lx.SHAPE_WORDS and w not in _PART_NOUNS
            and not (w in lx.AMBIGUOUS_SHAPES and k and (words[k - 1].isdigit()
                                                          or words[k - 1] in NUMBER_WORDS)
                     and words[k - 2 : k - 1] not in (["by"], ["x"]))
        ]  # fmt: skip  # "a canopy with four legs": its own; "5 blocks": cubes
        if len(named) != 2:
            return m.group(0)
        one = named[m.group(1).lower() != "former"]
        if lx.SHAPE_WORDS[named[0]] != lx.SHAPE_WORDS[named[1]]:
            said = f"the {one}"  # "the block": the definite name finds it
        else:
            said = "the first one" if m.group(1).lower() == "former" else "the second one"
        st.notes.append(f"read '{m.group(0)}' as {said}" + ("" if one in said else f" ({one})"))
        return said

    return _FORMER_LATTER.sub(which, text)


_COMPARED_TAIL = re.compile(
    r"(\b\d+\s+(?:high|long|wide)|\bof\s+\d+)\s+as\s+(?:the\s+(?:first|other|last|previous|"
    r"one\s+before)|it|that)(?:\s+one)?\b",
    re.IGNORECASE,
)
"""What a comparison was made with, left after its value was worked out."""


_OUTLINE = re.compile(
    r"(?:,\s*)?\b(?:one\s+)?(?:at|in)\s+(?:each|every|all\s+four|the\s+four|the)\s+corners?\s+of\s+"
    r"an?\s+(?:(\d+)\s*(?:x|by)\s*(\d+)|(\d+(?:\.\d+)?)\s*(mm|cm|m))\s+(?:square|outline|area|"
    r"space|footprint|zone)\b(?!\s+(?:slab|layer|base|plate|of))",
    re.IGNORECASE,
)
"""'four towers, one at each corner of a 5 by 5 square': a square outlined, not built."""
_MARK_CORNERS = re.compile(
    r"\bmark\s+(?:out\s+)?(?:the\s+)?(?:four\s+)?corners\s+of\s+(an?\s+\S+\s*(?:(?:x|by)\s*\d+\s*)?"
    r"(?:mm|cm|m\b)?\s*square)\s+with\s+([^.;]+)",
    re.IGNORECASE,
)
_THIN = ("tower", "towers", "cube", "cubes", "column", "columns", "stack", "stacks", "pillar",
         "pillars", "post", "posts", "block", "blocks", "pile", "piles")  # fmt: skip


def outline_corners(text: str, st: ReadState) -> str:
    """Towers or cubes at the corners of a square said by its size and never built: the four
    stand in two rows of two, the square's side apart at their outer faces ("one at each
    corner of a 5 by 5 square" built a 5 by 5 slab with a tower on each corner, silently)."""
    text = _MARK_CORNERS.sub(
        lambda m: f"put {m.group(2).strip()} at each corner of {m.group(1)}", text
    )
    m = _OUTLINE.search(text)
    if m is None:
        return text
    if m.group(1):
        side, other = int(m.group(1)), int(m.group(2))
    else:
        side = other = round(float(m.group(3)) * lx.UNITS_M[m.group(4).lower()] / st.cell.cube[0])
    before = text[: m.start()]
    nouns = [w for w in re.findall(r"[a-z]+", before.lower()) if w in lx.SHAPE_WORDS or w in _THIN]
    if side != other or side < 3 or not nouns or nouns[-1] not in _THIN:
        return text  # a rectangle's two gaps, or something wider than a cube at each corner
    said = m.group(0).strip(" ,")
    gap = side - 2
    st.notes.append(f"read '{said}' as four standing in two rows of two, {gap} cubes apart "
                    f"({side} parts across at their outer faces; no square built)")  # fmt: skip
    thin = "|".join(_THIN)
    noun = list(re.finditer(rf"\b(?:(\w+)\s+)?(?:\w+\s+)?({thin})\b", before, re.I))[-1]
    count = (noun.group(1) or "").lower()
    if not noun.group(2).lower().endswith("s"):  # "a tower of 3 at each corner": one at each
        if count not in ("a", "an", "one"):
            return text
        before = before[: noun.start()] + "four " + noun.group(0).split(None, 1)[-1] + "s" + (
            before[noun.end() :])  # fmt: skip
    elif count in set(NUMBER_WORDS) - {"four"} or (count.isdigit() and count != "4"):
        return text  # "three towers at the corners": not one at each of four
    return f"{before.rstrip(' ,')} in a 2 by 2 grid, {gap} cubes apart{text[m.end():]}"


_MORE_LEVELS = re.compile(
    r"(?:(?<=[.;!?])|(?<=^)|(?<=,)|(?<=\band)|(?<=\bthen)|(?<=\bplus))(\s*)(?:and\s+|then\s+|plus\s+)?"
    r"(?:just\s+)?((?:one|two|three|1|2|3)\s+more\s+(?:layers?|levels?|courses?|tiers?|storeys?|"
    r"stor(?:y|ies))\b)",
    re.IGNORECASE,
)
"""'Make a 3x3 slab. And one more layer.': a change said with no verb (it was ignored)."""


_SQUARE_BASE = re.compile(
    r"(?:\s*,\s*|\s+(?:with|on|and)\s+)(?:an?\s+|its\s+)?(?:square\s+(?:base|footprint|bottom|"
    r"plan)|(?:base|footprint|bottom)\s+(?:that\s+is\s+|being\s+)?square)\b|"
    r"(?:\s*,\s*)?\bnot\s+(?:a\s+)?flat(?:\s+one)?\b",
    re.IGNORECASE,
)
"""'a pyramid of 3 levels with a square base', 'a pyramid, not a flat one': a square one."""


_ONE_CUBE = (
    r"(?:just\s+|only\s+)?(?:a\s+single|one\s+single|a\s+lone|one|1|a)\s+(?:single\s+)?"
    r"(?:cube|block|brick)"
)
_AT_TOP = r"(?:on\s+(?:the\s+)?top|at\s+the\s+(?:top|peak|apex|tip|summit)|up\s+top)"
_APEX = re.compile(
    r"\s*(?:,\s*|\s)(?:and\s+|with\s+)?(?:"
    r"(?:(?:then\s+)?(?:go(?:ing)?|ris(?:e|ing)|build(?:ing)?|work(?:ing)?|step(?:ping)?|"
    r"narrow(?:ing)?|taper(?:ing)?)\s+(?:up\s+|in\s+)?)?(?:until|till|up\s+to)\s+"
    r"(?:there(?:'s|\s+is)\s+|it(?:'s|\s+is)\s+|you\s+(?:reach|get\s+to|have)\s+)?"
    rf"{_ONE_CUBE}(?:\s+{_AT_TOP})?"
    rf"|(?:topped|capped)(?:\s+off)?\s+(?:with|by)\s+{_ONE_CUBE}(?:\s+{_AT_TOP})?"
    rf"|end(?:s|ing)?\s+(?:in|with|at)\s+{_ONE_CUBE}(?:\s+{_AT_TOP})?"
    rf"|(?:the\s+|its\s+)?(?:top|apex|peak|tip)\s+(?:level\s+)?(?:is|being|=|:)\s*{_ONE_CUBE}"
    rf"|{_ONE_CUBE}\s+{_AT_TOP})\b(?!\s+of\b)",
    re.IGNORECASE,
)
"""'a pyramid, 4x4 base, go up until it's a single cube on top', 'a pyramid with a single cube
on top': the pyramid's own top level, not a cube added on it."""


def _apex(text: str, st: ReadState) -> str:
    """A pyramid's top said as one cube: the pyramid ends in one, nothing is added on it."""
    for m in reversed(list(_APEX.finditer(text))):
        sentence = re.split(r"[.;!?]\s", text[: m.start()])[-1]
        said = [w for w in re.findall(r"[a-z]+", sentence.lower()) if w in lx.SHAPE_WORDS]
        if said[-1:] != ["pyramid"] or re.search(r"\b(?:on|of)\s*$", sentence, re.I):
            continue
        after = re.split(r"\bpyramid\b", sentence, flags=re.I)[-1]
        if re.search(r"\b(?:put|place|add|stack|set|lay|build|then)\b", after, re.I):
            continue  # "a pyramid, then put one cube on top of it": a cube added
        st.notes.append(f"read '{m.group(0).strip(' ,')}' as the pyramid's own top: it ends "
                        "in one cube")  # fmt: skip
        text = text[: m.start()] + text[m.end() :]
    return text


def _square_pyramid(text: str, st: ReadState) -> str:
    """A pyramid said to stand on a square base (or not to be flat) is a square pyramid (it
    was built flat, one cube deep)."""
    pyramids = list(re.finditer(r"\bpyramid\b", text, re.IGNORECASE))
    m = _SQUARE_BASE.search(text)
    if len(pyramids) != 1 or m is None or m.start() < pyramids[0].start():
        return text
    if re.search(r"\b(?:flat|2-?d|two[\s-]dimensional)\s+pyramid", text, re.IGNORECASE):
        return text
    st.notes.append(f"read '{m.group(0).strip(' ,')}' as a square pyramid")
    p = pyramids[0]
    square = "" if re.search(r"\bsquare\s+$", text[: p.start()], re.I) else "square "
    return text[: p.start()] + square + text[p.start() : m.start()] + text[m.end() :]


_FLAT_NOUN = r"(?:slab|layer|panel|rectangle|square|sheet|plate|tile|grid|patch|pad|board)"
_UPRIGHT = re.compile(
    r"\b(?:vertical(?:ly)?|upright|on\s+(?:its\s+|an?\s+|one\s+)?(?:long\s+|short\s+)?(?:edge|end)|"
    r"(?:(?:stand(?:s|ing)?|stood)\s+up(?:right)?|(?:set|placed|put)\s+upright|(?:stand(?:s|ing)?|stood|"
    r"set|placed|put)\s+on\s+(?:its\s+|an?\s+|one\s+)?(?:long\s+|short\s+)?(?:edge|end|side))(?:\s+on\s+"
    r"(?:its\s+|an?\s+|one\s+)?(?:long\s+|short\s+)?(?:edge|end|side))?|like\s+a\s+wall)\b",
    re.IGNORECASE,
)
_FLAT_SIZED = re.compile(
    rf"\b(\d+)\s*(?:x|by)\s*(\d+)\s+(?:[a-z]+\s+)?{_FLAT_NOUN}s?\b|\b{_FLAT_NOUN}\s+(?:of\s+)?"
    r"(\d+)\s*(?:x|by)\s*(\d+)\b(?!\s*(?:x|by)\s*\d)",
    re.IGNORECASE,
)


def _upright(text: str, st: ReadState) -> str:
    """ "a 2 by 3 rectangle standing up on its edge", "a vertical 3x2 slab": a wall, its long
    side along the table unless it stands on its end (a flat slab was built, silently)."""
    out: list[str] = []
    for sentence in re.split(r"(?<=[.;!?])\s+", text):
        up, flat = _UPRIGHT.search(sentence), _FLAT_SIZED.search(sentence)
        if up is None or flat is None or len(_FLAT_SIZED.findall(sentence)) > 1:
            out.append(sentence)
            continue
        between = (
            sentence[up.end() : flat.start()] if up.end() <= flat.start()
            else sentence[flat.end() : up.start()]
        )  # fmt: skip
        owner = re.match(r"\s*(\w+)", sentence[up.end() :])
        if len(between) > 40 or families_said(between) or (
            up.end() <= flat.start() and between.strip(" ,").lower() not in ("", "a", "an")
        ) or bool(owner and families_said(owner.group(1))):
            out.append(sentence)  # "a 3x3 slab with a vertical tower on it": the tower's
            continue
        a, b = (int(v) for v in (flat.group(1, 2) if flat.group(1) else flat.group(3, 4)))
        on_end = re.search(r"\b(?:end|short)\b", up.group(0), re.IGNORECASE)
        long, high = (min(a, b), max(a, b)) if on_end else (max(a, b), min(a, b))
        noun = flat.group(0).split()[-1]
        noun = f" {noun}" if noun.isalpha() else ""  # "2 by 5" said with no noun
        st.notes.append(f"read '{up.group(0)}' of the {a} by {b}{noun} as a wall {long} long and "
                        f"{high} high")  # fmt: skip
        sentence = sentence[: up.start()] + sentence[up.end() :]
        sentence = _FLAT_SIZED.sub(f"wall {long} long and {high} high", sentence, count=1)
        sentence = re.sub(r",?\s*\bone\s+(?:cube|part|block)\s+thick\b", "", sentence, flags=re.I)
        out.append(sentence)
    return " ".join(out)


_DECK_LONG = re.compile(
    r"\b(?:deck|top|beam|lintel|roadway|walkway)\s+(?:(?:is|being|of)\s+)?(?:about\s+)?(\d+|two|three|"
    r"four|five|six|seven|eight)\s+(?:cubes?\s+|parts?\s+|blocks?\s+)?long\b",
    re.IGNORECASE,
)


def _deck_length(text: str, st: ReadState) -> str:
    """ "a bridge whose deck is 4 cubes long": a bridge's deck is its beams, one length; the
    length said is reported, not read as the bridge's (its pillars' span)."""
    if "bridge" not in families_said(text):
        return text
    beam = round(st.cell.part_types["beam"][0] / st.cell.cube[0])
    for m in reversed(list(_DECK_LONG.finditer(text))):
        said = m.group(0)
        if words_to_numbers([m.group(1).lower()])[0] == str(beam):
            st.notes.append(f"'{said}': a beam {beam} parts long, as built")
        else:
            st.material.append(said)
            st.notes.append(f"ignored '{said}': a bridge's deck is its beams, {beam} parts "
                            "long; say how far apart its pillars stand, or how long the bridge "
                            "is overall")  # fmt: skip
        text = text[: m.start()] + text[m.end() :]
    return text


def rewrite(text: str, st: ReadState) -> str:
    text = _MORE_LEVELS.sub(r"\1 add \2", text)
    text = _upright(text, st)
    text = _deck_length(text, st)
    text = _square_pyramid(text, st)
    if st.gap_m is not None or st.span_m is not None:  # "150 mm apart, not touching": said
        text = _NOT_TOUCHING.sub(lambda m: HANDLERS["{not_touching}"](m, st, ""), text)
    text = _apex(_level_labels(_level_list(text, st), st), st)
    text = _attributive(_sized_base(_beam_size(_single_layer(text), st), st), st)
    text = _post_and_beam(_ONE_SIZED.sub("a ", text), st)
    text = _for_use(text, st)
    text = _BEAM_HELD.sub(r"\1 resting on ", _OWN_LINTEL.sub(r"\1beam", text))
    text = _tetris(text, st)

    def on_end(m: re.Match[str]) -> str:
        st.notes.append(f"read '{m.group(0).strip()}' as a tower of {m.group(2)}")
        return f" {m.group(1)} tower of {m.group(2)} "

    text = _ON_END.sub(on_end, text)
    text = _described_again(text, st)
    text = _floors_as_levels(text, st)
    text = _count_of_plural(text, st)
    text = _counted_singular(text, st)
    text = _LOOSE_CUBES.sub(r" \1 1-cube towers, ", text)
    text = _ONE_OF.sub(_one_of, text)
    text = _LIKE_THAT.sub(" another one ", text)

    def copied(m: re.Match[str]) -> str:  # "a tower like the first one": another of it
        named = families_said(m.group(1))
        if not named or named[0] not in families_said(m.string[: m.start()]):
            return m.group(0)
        return f" another {m.group(1)} "

    text = _SAME_AS_BEFORE.sub(copied, text)
    text = _SAME_AGAIN.sub(
        lambda m: " another one but " if m.group(0).rstrip().endswith("but") else " another one ",
        text,
    )
    text = _EVERY_SIDE.sub(lambda m: HANDLERS["{every_side}"](m, st, ""), text)
    tall = _TALL_NOUN.search(text)
    if tall and not re.search(r"\d|\b(?:" + "|".join([*lx.SIZE_WORDS, *NUMBER_WORDS]) + r")\b",
                              text, re.I):  # fmt: skip
        # "a skyscraper": the noun says tall when nothing else gives a size
        st.notes.append(f"read '{tall.group(0)}' as a tall tower")
        text = text[: tall.start()] + "tall " + text[tall.start() :]

    def own_beam(m: re.Match[str]) -> str:
        st.notes.append(f"read '{m.group(0).strip()}' with the beam as the {m.group(1)}'s own")
        return f"{m.group(1)}{m.group(2)} "

    text = _OWN_BEAM.sub(own_beam, text)
    text = _ORDINAL_PLACES.sub(_ordinal_places, text)
    text = _former_latter(text, st)
    text = _DISTRIBUTE.sub(lambda m: HANDLERS["{distribute}"](m, st, ""), text)
    text = _OTHER_SIDE.sub(_other_side, text)
    text = _CORNERS.sub(lambda m: HANDLERS["{corners}"](m, st, ""), text)
    text = _another(SPACES.sub(" ", text))
    text = _bare_size(text, st)
    text = _PAIR_PLACES.sub(_pair_places, text)
    text = _sized_top(text)
    if (
        _LEGS.search(text)
        and _TOP.search(text)
        and not any(
            lx.SHAPE_WORDS.get(w) in ("canopy", "bridge", "arch", "t_shape")
            for w in re.findall(r"[a-z]+", text.lower())
        )
        and not re.search(r"\bt[\s-]*(?:shaped?|form)\b", text, re.I)  # "a T: top 5, leg 3"
    ):
        st.notes.append("legs with a top: read as a table")
        text = "a table with " + text
    for pattern, replacement, note in _REWRITES:

        def sub(m: re.Match[str], replacement: str = replacement, note: str = note) -> str:
            handler = HANDLERS.get(replacement)
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
                    SPACES.sub(" ", note.format(said, opposite=opposite, opposite2=opposite2))
                )
            return replacement.format(*groups, "", "", opposite=opposite, opposite2=opposite2)

        text = pattern.sub(sub, text)
    text = _LEVEL_ORDINAL.sub(" on top ", text)
    text = _COMPARED_TAIL.sub(r"\1", text)  # "twice as tall as the first" → "8 high as the first"
    text = _SIZE_AFTER_IT.sub(r"\3 \1 \2", text)  # "a tower next to it, 2 high": its own size
    text = _TOUCHING_IT.sub(r"\1, touching", text)
    for c in _COMPARISON.finditer(text):
        # "the left one taller than the right one": a comparison no rewrite turned into a value
        # ("two cubes taller than the walls" is a difference the grammar reads, or whose
        # number it reports unused)
        if _BY_HOW_MUCH.search(text[: c.start()]):
            continue
        said = c.group(0).strip()
        st.material.append(said)
        st.notes.append(f"ignored '{said}': SDI did not read this comparison into a size")
    m = _OPEN.search(text)
    if m and not any(w in lx.SHAPE_WORDS for w in re.findall(r"[a-z]+", text.lower())
                     if w not in ("base", "bottom") and w not in lx.AMBIGUOUS_SHAPES):  # fmt: skip
        size = "big " if m.group(1) else ""
        st.notes.append(
            f"read '{m.group(0)}' as a {size}3-D pyramid (wide at the base, rising to a point)"
        )
        text = text[: m.start()] + f"{size}3-D pyramid" + text[m.end() :]
    return SPACES.sub(" ", text)
