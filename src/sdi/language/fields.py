"""Commands written as a form's fields — a job list, an MES export, a spreadsheet row pasted as
text: "Tower | H: 4 | X (mm): 500 | Y (mm): 400", "Job 12 – Table – Legs: 4 – Top: beams",
"Loc: front left / Item: row / Qty cubes: 5". Each field is read by its key into the words the
rest of the front end reads (a height key into "4 high", a position key into "at x = 500 mm",
an item into the structure, a quantity into how many), with a note; fields that only file the
job (order, job, priority, revision, date) are dropped, and keys SDI does not know stay as words
so that the reading reports them. Text that is not a form — prose with a dash in it — is left
as it is."""

from __future__ import annotations

import re

from sdi.language.nouns import families_said
from sdi.language.structured import family_word
from sdi.spec import lexicon as lx

_SEPARATORS = (re.compile(r"\s*\|\s*"), re.compile(r"\s+[–—]\s+|\s+-\s+"), re.compile(r"\s+/\s+"))
_HMI_LINE = re.compile(
    r"\s*[A-Za-z_]+\s*:\s*[A-Za-z_]+(?:\s+[A-Za-z][A-Za-z_]*=[\w.+-]+)+\s*\.?\s*"
)
"""An HMI's line, "BUILD: TABLE LEGS=4 LEG_H=2": a heading and KEY=VALUE fields, nothing else."""
_KEY_VALUE = re.compile(r"\s+(?=[A-Za-z][A-Za-z_]*=\S)")
_FIELD = re.compile(
    r"^(?P<key>[A-Za-z][A-Za-z ._]{0,20}?)\s*(?:\((?P<unit>mm|cm|m|cubes?)\))?\s*[:=]\s*"
    r"(?P<value>.+)$"
)
_BARE_QTY = re.compile(r"^(?:qty|qyt|quantity|pcs|count)\s*[:=]?\s*(?P<value>\d+)$", re.IGNORECASE)
_BARE_SIZE = re.compile(r"^(?P<key>h|l|w|d)\s*(?P<value>\d+)$", re.IGNORECASE)  # "H 3"
_STAMP = re.compile(r"\d+[/.]\d+[/.]?\d*|\d{1,2}:\d{2}|\b(?:export|report|printed|page)\b", re.I)

_FILING = frozenset({
    "order", "job", "priority", "ref", "reference", "op", "rev", "revision", "line", "batch",
    "date", "time", "wk", "week", "shift", "cost centre", "cost center", "customer", "client",
    "owner", "due", "id", "status", "station", "cell", "operator", "requested by",
})  # fmt: skip
_ITEM = frozenset({"item", "type", "shape", "structure", "part", "object", "build"})
_QTY = frozenset({"qty", "quantity", "count", "number", "no", "pcs", "copies"})
_SIZE = {
    "h": "high", "ht": "high", "height": "high", "l": "long", "len": "long", "length": "long",
    "w": "wide", "width": "wide", "d": "deep", "depth": "deep", "levels": "levels",
    "tiers": "levels", "layers": "layers", "steps": "steps",
}  # fmt: skip
_LEG_HEIGHT = frozenset({"post h", "leg h", "legs h", "pillar h", "post height", "leg height",
                         "pillar height", "posts h", "pillars h"})  # fmt: skip
_LEGS = frozenset({"legs", "posts", "pillars", "supports"})
_PLACE = frozenset({"loc", "location", "position", "place", "where", "region", "area"})
_DIMS = frozenset({"size", "dims", "dimensions", "footprint"})
_CONTENTS = frozenset({"contents", "inside", "content"})
_PROSE = frozenset({"title", "summary", "description", "notes", "note", "comment", "comments",
                    "remarks", "details"})  # fmt: skip
_NO = frozenset({"no", "none", "n", "false", "0", "not allowed", "no beam", "no beams"})


def as_words(text: str, notes: list[str]) -> str:
    """`text` in words when it is a form of keyed fields; unchanged otherwise."""
    for sep in _SEPARATORS + ((_KEY_VALUE,) if _HMI_LINE.fullmatch(text) else ()):
        fields = [f.strip(" .;,") for f in sep.split(text.strip()) if f.strip(" .;,")]
        keyed = [f for f in fields if _FIELD.match(f) or _BARE_QTY.match(f) or _BARE_SIZE.match(f)]
        if len(fields) < 2 or not keyed or any(len(f) > 60 for f in fields):
            continue
        said = _read(fields)
        if said is None:
            continue
        notes.append(f"read the form's fields as '{said}'")
        return said
    return text


def _read(fields: list[str]) -> str | None:
    family: str | None = None
    titled = False  # a title field names the structure
    count: str | None = None
    rest: list[str] = []
    for field in fields:
        bare_qty = _BARE_QTY.match(field)
        if bare_qty:
            count = bare_qty.group("value")
            continue
        bare_size = _BARE_SIZE.match(field)
        if bare_size:
            rest.append(f"{bare_size.group('value')} {_SIZE[bare_size.group('key').lower()]}")
            continue
        m = _FIELD.match(field)
        if m is None:
            word = field.lower()
            if family is None and _family(word, field_only=True):
                family = _family(word, field_only=True)
            elif family is None and _family(word.split(",")[0]):  # "Pyramid, 3 levels"
                family = _family(word.split(",")[0])
                rest.append(field.split(",", 1)[1])
            elif not any(word.startswith(f) for f in _FILING) and not _STAMP.search(field):
                rest.append(field)
            continue
        key = " ".join(m.group("key").lower().replace("_", " ").split())
        unit = m.group("unit")
        value = re.sub(r"\s+(?:cubes?|blocks?|parts?)$", "", m.group("value").strip(), flags=re.I)
        value = value.replace("_", " ")  # "POS=BACK_LEFT"
        unit_said = f" {unit}" if unit and not unit.startswith("cube") else ""
        if key in _FILING or any(key.startswith(f + " ") for f in _FILING):
            continue
        if key in _ITEM and family is None and _family(value.lower(), field_only=True):
            family = _family(value.lower(), field_only=True)
        elif key in _QTY or key.startswith(("qty ", "quantity ")):
            if key.endswith(("cubes", "cube", "parts")):  # "Qty cubes: 5": how many parts
                rest.append(f"of {value} cubes")
            else:
                count = value
        elif key in _SIZE:
            rest.append(f"{value}{unit_said} {_SIZE[key]}")
        elif key in ("t", "thickness") and family == "wall":  # "WALL L=6 H=3 T=1"
            rest.append(f"{value}{unit_said} thick")
        elif key in _LEG_HEIGHT:
            rest.append(f"legs {value}{unit_said} high")
        elif key in _LEGS:
            rest.append(f"{value} legs")
        elif key in ("dir", "direction", "orientation") and re.fullmatch(
            r"(left|right|front|back)\s+(left|right|front|back)", value, re.I
        ):  # "DIR=LEFT_RIGHT"
            rest.append(re.sub(r"(\w+)\s+(\w+)", r"from \1 to \2", value.lower()))
        elif key in ("x", "y"):
            rest.append(f"at {key} = {value}{unit_said or ' m'}")
        elif key in _PLACE:
            plain = re.fullmatch(r"(?:the\s+)?(?:front|back|left|right|centre|center|middle)"
                                 r"(?:\s+(?:left|right|corner))*", value, re.I)  # fmt: skip
            rest.append(f"at the {value}" if plain else value)
        elif key in _DIMS:
            rest.append(f"{value}{unit_said}")
        elif key == "top":
            rest.append(f"with {value} on top")
        elif key in ("beam", "beams"):
            rest.append("with no beams" if value.lower() in _NO else "with a beam")
        elif key in _PROSE:  # "Title: Flat grid 2x6", "Notes: one layer only": words to read
            rest.append(value)
            titled = titled or (key in ("title", "summary") and bool(families_said(value)))
        elif key in _CONTENTS:
            cubes = re.match(r"(\d+|one|a|two|three)\s+cubes?\b", value, re.I)
            if cubes:  # "Contents: 1 cube, centred inside": a column of them in its middle
                rest.append(f"and a tower of {cubes.group(1)} in the middle of it")
            else:
                rest.append(f"and {value} inside it")
        else:
            rest.append(f"{key} {value}")
    if family is None and titled and len([r for r in rest if families_said(r)]) == 1:
        return ", ".join(rest)  # "Type: Task | Title: Flat grid 2x6": the title names it
    if family is None:
        return None
    n = count if count and count.isdigit() and int(count) > 1 else None
    head = f"{n} {family}s" if n else f"{'an' if family[0] in 'aeiou' else 'a'} {family}"
    return ", ".join([head, *rest])


def _family(word: str, field_only: bool = False) -> str | None:
    """The structure word a field names, singular ("Tower", "towers" → "tower"), as the data
    reader reads it (`structured.family_word`); a word that may name something else ("block")
    only when it is the whole field (`field_only`)."""
    w = family_word(word)
    return w if w and (field_only or w not in lx.AMBIGUOUS_SHAPES) else None
