"""Claims: what a command says must hold of the whole reading, checked against it.

"A row of 6, not stacked, all on the table", "two towers and they mustn't touch", "a ring
without anything inside it", "one tower, nothing else": these words add no structure, size
or place — they state a property of what is built. `take` cuts them out of the text before
the grammar reads it (so they are not left over as unused words), and `check` tests each
against the finished reading: a claim that holds becomes a note saying so; one that does
not is material (the plan is `partial`), with a note naming the words.
"""

from __future__ import annotations

import re

from sdi.errors import SDIError, SpecError
from sdi.language.nouns import families_said, shape_alternation
from sdi.language.state import ReadState
from sdi.spec import lexicon as lx
from sdi.spec.numbers import words_to_numbers
from sdi.spec.structure_spec import Spec, StructureSpec

_N = r"(?:,\s*)?\b(?:and\s+|but\s+)?"  # the joint before a claim
_THEM = (
    r"(?:they|them|it|both|all|each|none\s+of\s+them|"
    r"the\s+(?!(?:left|right|front|back|middle|centre|center|table|side|edge)\b)\w+)"
)
_INSIDE = r"(?:inside|within|in\s+the\s+(?:middle|centre|center)|in\s+it)(?:\s+(?:it|of\s+it))?"

_FAMILY = r"(?:" + shape_alternation() + r")"
_COUNT = r"(\d+|two|three|four|five|six|seven|eight|nine|ten)"

_CLAIMS: tuple[tuple[str, re.Pattern[str]], ...] = tuple(
    (kind, re.compile(pattern, re.IGNORECASE))
    for kind, pattern in (
        # nothing stands on anything: every structure one layer on the table
        ("flat", _N + r"(?:(?:all\s+|each\s+)?(?:not|never)|none(?:\s+of\s+them)?)\s+"
                      r"stacked(?:\s+up)?(?:\s+on\s+(?:each\s+other|one\s+another|top\s+of\s+each\s+other))?\b"),
        ("flat", _N + r"(?:all|each(?:\s+one)?|every\s+one|both)\s+(?:of\s+them\s+)?"
                      r"(?:lying\s+|laid\s+)?(?:flat\s+|directly\s+|straight\s+)?on\s+the\s+(?:table|ground|floor)\b"),
        ("flat", _N + r"(?:but\s+)?(?:no|without\s+a|not\s+a)\s+(?:second|2nd|third|3rd|other|"
                      r"extra|further|more)\s+(?:layers?|levels?|courses?|tiers?)"
                      r"(?:\s*,?\s*just\s+flat)?\b"),
        ("flat", _N + r"(?:lying|laid|lie|lay|laying)\s+flat"
                      r"(?:\s+on\s+the\s+(?:table|ground|floor))?\b"),
        # standing on another structure, not on the table
        ("raised", _N + r"(?:but\s+)?not\s+(?:standing\s+|directly\s+)?on\s+(?:the\s+)?"
                        r"(?:table|floor|ground)\b"),
        # nothing on top of what is named
        ("bare", _N + r"(?:please\s+)?(?:do\s+not|never)\s+(?:stack|put|place|build)\s+"
                      r"anything\s+(?:else\s+)?(?:on\s+top\s+of|on|onto|above)\s+" + _THEM + r"\b"),
        ("bare", _N + r"(?:with\s+)?(?:nothing|no\s+(?:cubes?|parts?|blocks?|bricks?|"
                      r"more\s+cubes?))"
                      r"\s+(?:else\s+)?(?:(?:stacked|piled|put|placed|sitting|standing)\s+)?"
                      r"(?:on\s+top|on\s+it|on\s+them|above\s+it)"
                      r"(?:\s+of\s+(?:it|them))?(?:\s+at\s+all)?\b"),
        # separate structures with space between them
        ("apart", _N + r"(?:and\s+)?(?:make\s+sure\s+(?:that\s+)?|ensure\s+(?:that\s+)?|so\s+"
                       r"that\s+)?no\s+two(?:\s+(?:of\s+them|\w+))?\s+(?:touch|are\s+touching|"
                       r"touching)\b"),
        ("apart", _N + _THEM + r"\s+(?:must|should|may|can|do|does|will|shall)\s*(?:not|never)\s+"
                       r"touch(?:\s+(?:each\s+other|one\s+another))?\b"),
        # "two towers of 3 but NOT joined at the top": no beam across them (read as joined)
        ("apart", _N + r"(?:(?:they\s+are|are|(?:must|should)\s+be)\s+)?(?:not|never)\s+(?:joined|"
                       r"connected|linked|bridged)(?:\s+(?:together|to\s+each\s+other))?(?:\s+(?:at|"
                       r"across|over|along)\s+(?:the\s+)?tops?)?\b"),
        # a hollow structure left empty
        ("empty", _N + r"(?:with\s+)?(?:nothing|no\s+(?:cubes?|parts?|blocks?|bricks?))\s+"
                       + _INSIDE + r"\b"),
        ("empty", _N + r"without\s+anything\s+" + _INSIDE + r"\b"),
        ("empty", _N + r"(?:and\s+)?(?:with\s+)?no\s+(?:cubes?|blocks?|parts?|bricks?)\s+there\b"),
        ("empty", _N + r"inside\s+(?:it\s+)?nothing\b"),
        ("empty", _N + r"(?:left\s+)?empty\s+(?:inside|in\s+the\s+(?:middle|centre|center))\b"),
        # only what is named
        ("only", _N + r"nothing\s+else(?:\s+on\s+the\s+table)?\b"),
        ("only", _N + r"no\s+other\s+(?:things?|structures?|parts?|objects?|stuff)"
                      r"(?:\s+on\s+the\s+table)?\b"),
        ("only", _N + r"no\s+more\s*,?\s*(?:and\s+)?no\s+less\b"),
        # how many of a family there are: "total 2 tower", "three towers in all"
        ("count", _N + r"(?:in\s+)?total(?:\s+of)?\s*:?\s*" + _COUNT + r"\s+(" + _FAMILY + r")\b"),
        ("count", _N + r"(?:so\s+)?" + _COUNT + r"\s+(" + _FAMILY + r")\s+(?:in\s+total|in\s+all|"
                       r"altogether|overall)\b"),
        # each structure standing on its own on the table
        ("bare", _N + r"(?:(?:all|each|both)\s+)?(?:(?:of\s+)?(?:the\s+)?(?:two|three|four|five|"
                      r"\d+)\s+)?(?:items?|structures?|pieces?|of\s+them|parts?)?\s*(?:are\s+|is\s+|"
                      r"must\s+be\s+|shall\s+be\s+)?free[\s-]?standing\b"),
        # how many parts in all: "total part count 25", "Expected: 8 parts total"
        ("parts", _N + r"(?:(?:the\s+)?total\s+)?(?:part|cube|block)\s+count\s*(?:of|is|=|:)?\s*"
                       r"(\d+)\b"),
        ("parts", _N + r"(?:expected\s*:\s*)?(\d+)\s+(?:parts|cubes|blocks)\s+(?:in\s+)?(?:total|"
                       r"in\s+all|altogether|overall)\b"),
        # fewer parts than a bound: "keep it under 10 cubes"
        ("under", _N + r"(?:but\s+)?(?:keep(?:ing)?\s+(?:it|them|everything)\s+|"
                       r"(?:in|with|using)\s+)?(?:under|below|fewer\s+than|less\s+than)\s+" + _COUNT
                       + r"\s+(?:cubes|blocks|parts|bricks)\b"
                       r"(?!\s*(?:tall|high|long|wide|deep|in\s+height))"),
        # long structures running the same way
        ("parallel", _N + r"(?:(?:both|all|that\s+are|which\s+are|they\s+are)\s+)?parallel"
                           r"(?:\s+to\s+(?:each\s+other|one\s+another))?\b(?!\s+to\s+the\b)"),
        # "two walls facing each other", "… 4x2 facing, 3 apart": face to face, the same way
        ("parallel", _N + r"(?:(?:that\s+are|which\s+are|they\s+are|standing)\s+)?facing"
                           r"(?:\s+(?:each\s+other|one\s+another))?\b(?!\s+(?:the|a|an|it|them|"
                           r"left|right|front|back|north|south|east|west|forward|away|towards?)\b)"),
        # "three walls …, one behind the other" (read so in `normalise`): parallel in one line
        ("parallel", _N + r"one\s+behind\s+another\b"),
        # every structure as high as the others
        ("same", _N + r"(?:all\s+|both\s+)?(?:(?:of\s+)?the\s+)?same\s+height\b"
                      r"(?:\s+as\s+(?:each\s+other|one\s+another))?(?!\s+as\b)"),
        ("same", _N + r"(?:all\s+|both\s+)?(?:equally\s+(?:high|tall)|equal\s+(?:in\s+)?height)\b"),
    )
)  # fmt: skip

_HOLDS = {
    "flat": "every structure is one layer on the table",
    "bare": "nothing stands on another structure",
    "apart": "the structures stand apart",
    "empty": "nothing stands inside it",
    "only": "only what is named is built",
    "count": "as many as said",
    "raised": "it stands on another structure",
    "parallel": "they run the same way",
    "same": "every structure as high as the others",
}
_HOLLOW = frozenset({"enclosure", "castle", "u_shape"})
_FOOTPRINTS = frozenset({"l_shape", "t_shape", "u_shape", "cross"})


def take(text: str, st: ReadState) -> str:
    """`text` without the claims it states, each kept in `st.claims`."""
    for kind, pattern in _CLAIMS:

        def cut(m: re.Match[str], kind: str = kind) -> str:
            if kind == "count" and not _named_before(m):
                return m.group(0)  # "three towers in total, each 2 high": they are named here
            if kind == "parts" and not _SIZED.search(m.string[: m.start()]):
                return m.group(0)  # "a tower, 6 cubes in total": the tower's only size
            if kind == "parallel" and st.line is None and not _RUNS_X.search(m.string):
                st.line = "x"  # walls running left to right stand parallel one behind the other
            if (
                kind == "empty"
                and re.search(r"\bempty\s+(?:inside|in\s+the)", m.group(0), re.I)
                and not _HOLLOW & set(families_said(m.string))
            ):
                # "a square, 3 by 3, empty in the middle": a ring, not a slab
                return " , hollow in the middle , "
            if kind == "same" and re.search(
                r"\b(?:none|not|no|never|nor)\b[^,.;]*$", m.string[: m.start()], re.I
            ):
                return m.group(0)  # "none of them the same height": the opposite
            st.claims.append((kind, m.group(0).strip(" ,")))
            return " , "

        text = pattern.sub(cut, text)
    return text


def _one_layer(spec: Spec) -> bool:
    for s in spec.structures:
        if s.shape in ("row", "grid"):
            continue
        if s.shape in _FOOTPRINTS and getattr(s, "height", None) in (None, 1):
            continue  # "a letter U lying flat": a footprint is one layer unless raised
        height = getattr(s, "height", None) or (s.count if s.shape == "tower" else None)
        if height != 1:
            return False
    return True


def _holds(kind: str, spec: Spec) -> bool:
    on_top = any(r.kind == "on_top_of" for r in spec.relations)
    if kind == "flat":
        return _one_layer(spec) and not on_top
    if kind == "bare":
        return not on_top
    if kind == "apart":
        touching = any(r.gap_m == 0 for r in spec.relations) or spec.gap_m == 0
        return len(spec.structures) >= 2 and not touching and not on_top
    if kind == "empty":
        hollow = any(s.shape in _HOLLOW for s in spec.structures)
        return hollow and not any(r.kind == "around" for r in spec.relations)
    if kind == "raised":
        return on_top
    if kind == "parallel":
        long = [s for s in spec.structures if s.shape in ("wall", "row")]
        beside = [r for r in spec.relations if r.kind == "next_to"]
        sides = {r.side for r in beside}
        along = {s.axis or "y" for s in long}
        # side by side across their length: behind or in front for walls running left-right
        facing = sides <= ({"front", "back", None} if along == {"y"} else {"left", "right", None})
        lined = (spec.line == "x") == (along == {"y"}) or bool(beside)
        return len(long) >= 2 and len(along) == 1 and facing and lined
    if kind == "same":
        heights = {_height(s) for s in spec.structures}
        return len(spec.structures) >= 2 and len(heights) == 1 and None not in heights
    return kind == "only"


def _height(s: StructureSpec) -> int | None:
    return getattr(s, "height", None) or (getattr(s, "count", None) if s.shape == "tower" else None)


_RUNS_X = re.compile(r"\bfront\s+to\s+back\b|\balong\s+x\b|\bback\s+to\s+front\b", re.I)
_SIZED = re.compile(r"\d|\b(?:one|two|three|four|five|six|seven|eight|nine|ten)\b", re.I)


def _named_before(m: re.Match[str]) -> bool:
    """The family a count claim counts was named before the claim."""
    family = lx.SHAPE_WORDS.get(m.group(2).lower())
    before = re.findall(r"[a-z]+", m.string[: m.start()].lower())
    return any(lx.SHAPE_WORDS.get(w) == family for w in before)


def _counted(said: str, spec: Spec) -> bool:
    """ "total 2 tower": as many structures of that family as said."""
    m = re.search(_COUNT + r"\s+(" + _FAMILY + r")\b", said, re.IGNORECASE)
    if m is None:
        return False
    n = int(words_to_numbers([m.group(1).lower()])[0])
    family = lx.SHAPE_WORDS.get(m.group(2).lower())
    return sum(s.shape == family for s in spec.structures) == n


def check(spec: Spec, st: ReadState) -> None:
    """A note for each claim that holds; material and a note for each that does not."""
    for kind, said in st.claims:
        if kind == "result":
            _result(said, spec, st)
            continue
        if kind in ("parts", "under"):
            _total(said, spec, st)
            continue
        if _counted(said, spec) if kind == "count" else _holds(kind, spec):
            st.notes.append(f"'{said}': holds, {_HOLDS[kind]}")
        else:
            st.material.append(said)
            st.notes.append(f"ignored '{said}': the reading does not keep it ({_HOLDS[kind]})")


_SIZES = ("length", "width", "height", "steps", "count")


def _result(said: str, spec: Spec, st: ReadState) -> None:
    """ "Expected result: a 2 x 3 x 2 block", "should come out as a block 2 deep": the result
    the command describes, read on its own and compared with what the reading builds."""
    from sdi.language.reader import read  # the description is a command of its own

    described = re.sub(r"^.*?(?=\b(?:a|an|one)\s)", "", said, count=1, flags=re.IGNORECASE)
    try:
        (want,) = read(described, st.cell).spec.structures
    except (SpecError, ValueError):
        st.notes.append(f"read '{said}' as a description, not a structure")
        return
    if len(spec.structures) != 1:
        # several structures said to make one: at least as many parts as it has
        counts = [_parts(s, st) for s in spec.structures]
        wanted = _parts(want, st)
        total = sum(c for c in counts if c is not None)
        numbers = [w for w in words_to_numbers(re.findall(r"[a-z]+|\d+", described.lower()))
                   if w.isdigit()]  # fmt: skip
        sized = len(numbers) >= len(want.model_fields_set & set(_SIZES))  # no default in it
        if sized and wanted is not None and None not in counts and total != wanted:
            st.material.append(said)
            st.notes.append(f"ignored '{said}': the reading builds {total} parts in "
                            f"{len(spec.structures)} structures, that result {wanted}")  # fmt: skip
            return
        st.notes.append(f"read '{said}' as a description of the {len(spec.structures)} "
                        "structures together; their parts add up, the arrangement is not "
                        "checked")  # fmt: skip
        return
    (got,) = spec.structures
    if _same(want, got):
        st.notes.append(f"'{said}': holds, the reading builds that")
        return
    st.material.append(said)
    st.notes.append(f"ignored '{said}': the reading builds a {got.shape} "
                    f"{_sizes(got)}, not what it describes")  # fmt: skip


def _sizes(s: StructureSpec) -> str:
    d = s.model_dump(include=set(_SIZES), exclude_none=True)
    return " ".join(f"{k} {v}" for k, v in d.items()) or "of its default size"


def _same(want: StructureSpec, got: StructureSpec) -> bool:
    """The described structure is the one built: its family, and every size it gives (a
    footprint in either turn)."""
    if want.shape != got.shape:
        return False
    w = want.model_dump(include=set(_SIZES), exclude_none=True)
    g = got.model_dump(include=set(_SIZES), exclude_none=True)
    foot_w = sorted(v for k, v in w.items() if k in ("length", "width"))
    foot_g = sorted(v for k, v in g.items() if k in ("length", "width"))
    if foot_w and foot_w != foot_g[: len(foot_w)] and foot_w != foot_g[-len(foot_w) :]:
        return False
    return all(g.get(k) == v for k, v in w.items() if k not in ("length", "width"))


def _parts(s: StructureSpec, st: ReadState) -> int | None:
    """How many parts the family's generator makes of `s` (None: it cannot make it)."""
    from sdi.design.composer import part_sizes  # the generators count, as they will build
    from sdi.design.shapes import generate

    try:
        return len(generate(s, part_sizes(st.cell, s.part)))
    except (SDIError, ValueError):
        return None


def _total(said: str, spec: Spec, st: ReadState) -> None:
    """ "total part count 25": as many parts as the reading builds, where the families say;
    "keep it under 10 cubes": fewer than that."""
    numbers = [w for w in words_to_numbers(re.findall(r"\d+|[a-z]+", said.lower())) if w.isdigit()]
    if not numbers:
        return
    want = int(numbers[-1])
    counts = [_parts(s, st) for s in spec.structures]
    if any(c is None for c in counts):
        st.notes.append(f"'{said}': not checked, a structure cannot be built as read")
        return
    got = sum(c for c in counts if c is not None)
    if got == want or (re.search(r"\b(?:under|below|fewer|less)\b", said, re.I) and got < want):
        st.notes.append(f"'{said}': holds, {got} parts")
        return
    st.material.append(said)
    st.notes.append(f"ignored '{said}': the reading builds {got} parts")
