"""The phrase grammar: one phrase of a command → its structures as drafts (`SpecDraft`), with
no model; the family check (`sdi.language.families`) turns each draft into its family's spec.

The command is tokenised (numbers in words become digits, units and symbols split off), then
read in passes, each marking the tokens it explains:

1. coordinates (``x = 0.45 m``, ``at (0.4, 0.3)``), rotations, axes, dimension groups
   (``3 by 4``, ``2x2x2``) and measurements with units (``20 cm tall``);
2. shape nouns, with context deciding words that are also part nouns ("a block" vs "5 blocks");
3. segmentation: every remaining token is attached to the structure it modifies, split at
   conjunctions between shape nouns ("a tower of 5 and a wall 3 high");
4. attributes per structure: counts, levels, steps, spans, vague sizes, regions, gaps,
   multiplicity ("two towers"); compounds ("two towers joined by a bridge" → a bridge on
   tower-high pillars, "a castle with corner towers 3 high").

A command with no recognisable structure fails with `SpecError`, saying what was understood.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, field
from typing import Any

from pydantic import ValidationError

from sdi.errors import SpecError
from sdi.model.cell import CellConfig
from sdi.spec import lexicon as lx
from sdi.spec.numbers import QUANTITY_WORDS, words_to_numbers
from sdi.spec.structure_spec import SpecDraft, StructureDraft

_TOKEN = re.compile(r"\d+(?:\.\d+)?|\.\d+|[a-z]+|[=:(),;°×*+&\-/]")
_SYMBOLS = {"×": " x ", "–": "-", "—": "-", "’": "", "'": "", "°": " deg ", "\u00a0": " "}
_SIDES = ("left", "right", "front", "back")

# Default parameters of each family by vague size class (S, M, L). Keys are StructureDraft fields.
SIZE_TABLE: dict[str, dict[str, tuple[int, int, int]]] = {
    "tower": {"height": (2, 3, 6)},
    "row": {"length": (3, 5, 8)},
    "grid": {"length": (2, 3, 4), "width": (2, 3, 4)},
    "wall": {"length": (3, 4, 6), "height": (1, 2, 4)},
    "block": {"length": (2, 3, 3), "width": (2, 3, 3), "height": (1, 2, 3)},
    "pack": {"count": (4, 8, 12)},
    "pyramid": {"length": (2, 3, 4)},
    "staircase": {"steps": (2, 3, 5), "width": (1, 2, 3)},
    "bridge": {"height": (1, 2, 3), "spans": (1, 1, 2)},
    "arch": {"height": (1, 2, 3)},
    "canopy": {"height": (2, 3, 4)},
    "enclosure": {"length": (3, 4, 5), "width": (3, 4, 5)},
    "castle": {"length": (3, 4, 5), "width": (3, 4, 5), "height": (1, 1, 2)},
    "l_shape": {"length": (2, 3, 4), "width": (2, 3, 4)},
    "u_shape": {"length": (3, 3, 4), "width": (2, 3, 4)},
    "t_shape": {"length": (3, 3, 5), "width": (2, 3, 4)},
    "cross": {"length": (3, 3, 5)},
}
# The parameter a bare number sets ("a tower of 5", "a 4 staircase").
PRIMARY = {
    "tower": "height", "row": "length", "grid": "count", "wall": "length", "block": "count",
    "pack": "count", "pyramid": "length", "staircase": "steps", "bridge": "height",
    "arch": "height", "canopy": "height", "enclosure": "length", "castle": "length",
    "l_shape": "length", "u_shape": "length", "t_shape": "length", "cross": "length",
}  # fmt: skip
_FAMILY_WORD = {"canopy": "table"}
"""The everyday word for a family whose name operators do not say, in notes."""
# Which field a measurement in metres sets when no dimension word says.
PRIMARY_M = {
    "tower": "height_m",
    "staircase": "height_m",
    "canopy": "height_m",
    "bridge": "height_m",
}
# Shapes that hold pillars: a tower-like noun after them ("with legs 3 high") is part of them.
# Words that may stand before an imperative verb at the start of a clause.
CLAUSE_LEAD = {
    "please", "now", "then", "and", ",", ":", ";", "to", "you", "can", "could", "would",
    "also", "just", "lets", "let", "us", "i", "we", "want", "need", "go", "ahead", "kindly",
    "first", "next", "finally", "robot", "hey", "ok", "okay",
}  # fmt: skip
# Words after "packed", "stacked"…: the shape they imply when no noun names one.
IMPLYING_WORDS = {
    "packed": "pack", "tightly": "pack", "densely": "pack", "compactly": "pack",
    "stacked": "tower", "piled": "tower",
}  # fmt: skip
LETTER_HEADS = {"l_shape", "u_shape", "t_shape", "cross"}
# Nouns that name a part of a bigger structure when linked to it ("a castle with towers").
COMPONENTS = {
    "castle": {"enclosure", "wall", "tower", "row"},
    "canopy": {"tower", "canopy", "grid"},
    "bridge": {"tower"},
    "arch": {"tower"},
    "enclosure": {"wall"},
    "u_shape": {"wall"},
    "l_shape": {"wall"},
    "t_shape": {"wall"},
}
_SIZE_TOKENS = {"x", "by", "high", "tall", "long", "wide", "cube", "cubes"}
"""Words of a size said between a structure and its part, with no link word."""
LINKS = {
    "with", "of", ":", "having", "has", "whose", "on", "atop", "featuring", "including", "where",
    "and", ",", "plus", "each", "at", "between", "over", "across", "upon", "from", "supported",
    "resting", "standing", "carried",
}  # fmt: skip
# "a 5-cube bar", "5 cubes at the bottom": a count that names a dimension of the shape.
PART_NOUN_KEYS = {
    "bar": "length", "base": "length", "bottom": "length", "stem": "width",
    "arms": "arms", "arm": "arms", "sides": "arms", "side": "arms", "legs": "height",
    "leg": "height",
}  # fmt: skip


_T_PARTS = {"bar": "length", "top": "length", "crossbar": "length", "head": "length",
            "stem": "width", "trunk": "width", "upright": "width", "leg": "width"}  # fmt: skip
"""A T's parts: its bar (the T's length) and its stem (its width)."""

_MOVED_OVER = frozenset({"to", "towards", "toward", "on", "at", "from", "the", "left", "right",
                         "there", "here"})  # fmt: skip
_ON_LEGS = frozenset({"bridge", "arch", "canopy"})
"""Shapes that span an opening on legs or pillars: "legs 3" is how high they are, not an arm's
length; a gap said of them is their span."""

_SECOND_SIZE = frozenset({"levels", "level", "layers", "layer", "high", "tall", "steps", "long",
                          "wide", "deep", "courses", "storeys", "stories", "tiers"})  # fmt: skip
"""Words after the second of two numbers said with a comma that make it a size of its own
("a base of 4, 3 levels high"), not a list ("of 2, 3")."""


_LISTED_SIZE = {"tower": ("high", "tall"), "row": ("long",), "wall": ("long",),
                "staircase": ("steps",)}  # fmt: skip
"""The size word a list of values ends with that names the family's main size ("towers of 2,
3 and 4 high"): used with the list."""


@dataclass
class Tok:
    text: str
    kind: str  # "num" | "word" | "sym"
    value: float = 0.0
    used: bool = False


class _Slots(dict[str, Any]):
    """A structure's slots; a second, different value for a filled slot is a conflict."""

    def __init__(self) -> None:
        super().__init__()
        self.conflicts: list[tuple[str, Any, Any]] = []

    def setdefault(self, key: str, default: Any = None) -> Any:
        if (
            key in self
            and (not key.startswith("_") or key == "_count")
            and isinstance(default, int | float)
            and isinstance(self[key], int | float)
            and self[key] != default
        ):
            self.conflicts.append((key, self[key], default))
        return super().setdefault(key, default)


@dataclass
class Hit:
    """A structure mentioned in the command."""

    index: int
    shape: str
    plural: bool
    params: dict[str, Any] = field(default_factory=_Slots)
    verb: bool = False
    multiplicity: int = 1
    start: int = 0
    end: int = 0


_FLAT_LEADS = frozenset(
    {"a", "an", "one", "single", "flat", "square", "rectangular", "solid", "thin", "plain",
     "simple", "low", "another", "second", "new", "layer"}
)  # fmt: skip
"""Words before "pad", "layer", "deck" … that make it a structure ("a square pad")."""


def tokenize(command: str) -> list[Tok]:
    text = command.lower()
    for a, b in _SYMBOLS.items():
        text = text.replace(a, b)
    raw = words_to_numbers(_TOKEN.findall(text))
    toks: list[Tok] = []
    for word in raw:
        if word[0].isdigit() or (word[0] == "." and len(word) > 1):
            toks.append(Tok(word, "num", float(word)))
        elif word.isalpha():
            toks.append(Tok(word, "word"))
        else:
            toks.append(Tok(word, "sym"))
    # Signs: "- 0.1" after "=", ":", "(", "," or at the start is a negative number.
    out: list[Tok] = []
    for k, t in enumerate(toks):
        if t.text == "-" and k + 1 < len(toks) and toks[k + 1].kind == "num":
            prev = out[-1].text if out else "("
            if prev in ("=", ":", "(", ",", "at", "to", "of", "is"):
                toks[k + 1].value = -toks[k + 1].value
                toks[k + 1].text = "-" + toks[k + 1].text
                continue
        if t.text in ("-", "/"):
            continue  # "3-cube", "l-shaped", "and/or": joiners carry no meaning here
        out.append(t)
    return out


class _Parser:
    def __init__(self, command: str, cell: CellConfig) -> None:
        self.command = command
        self.cell = cell
        self.toks = tokenize(command)
        self.notes: list[str] = []
        self.coords: list[tuple[int, str, float]] = []  # (token index, axis, metres)
        self.yaws: list[tuple[int, float]] = []
        self.axes: list[tuple[int, str]] = []
        self.long_side = False  # "long side left to right": the longer side along the axis
        self.dims: list[tuple[int, list[int]]] = []
        self.measures: list[tuple[int, float, str | None]] = []  # (index, metres, field)
        self.hits: list[Hit] = []
        self.beam = False

    # -- helpers -------------------------------------------------------------------------
    def word(self, k: int) -> str:
        return self.toks[k].text if 0 <= k < len(self.toks) else ""

    def _count_of_sized(self, k: int) -> bool:
        """The number at `k` counts structures a vague size word describes ("two tall towers",
        "one tall tower"), not their size ("a 5 tall tower", "3 high tower")."""
        adjective, noun = self.word(k + 1), self.word(k + 2)
        if (
            adjective not in ("tall", "short", "low")
            or self.word(k - 1) in ("a", "an", "the")
            or re.search(rf"\d\s*-\s*{adjective}\b", self.command, re.IGNORECASE)  # "3-tall"
        ):
            return False
        family = lx.SHAPE_WORDS.get(noun)
        if family is None or noun in lx.AMBIGUOUS_SHAPES:
            return False
        plural = noun.endswith("s") and lx.SHAPE_WORDS.get(noun[:-1]) == family
        return plural or self.toks[k].value == 1

    def is_num(self, k: int) -> bool:
        return 0 <= k < len(self.toks) and self.toks[k].kind == "num"

    def _metres(self, k: int, axis: str | None = None) -> tuple[float, int]:
        """Value of the number at k in metres and the index after it (with its unit). A
        coordinate said without a unit is in the unit that puts it on the table: "x 45" is
        45 cm, "x 450" 450 mm."""
        value = self.toks[k].value
        if k + 1 < len(self.toks) and self.word(k + 1) in lx.UNITS_M:
            self.toks[k + 1].used = True
            return value * lx.UNITS_M[self.word(k + 1)], k + 2
        if abs(value) > 2.0:
            ws = self.cell.workspace
            lo, hi = {"x": (ws.x_min, ws.x_max), "y": (ws.y_min, ws.y_max)}.get(axis or "", (0, 1))
            unit = "cm" if lo <= value / 100.0 <= hi or not lo <= value / 1000.0 <= hi else "mm"
            self.notes.append(f"read {value:g} without a unit as {value:g} {unit}")
            return value * lx.UNITS_M[unit], k + 1
        return value, k + 1

    # -- pass 1: coordinates, rotation, axes, dimension groups, measurements --------------
    def scan_geometry(self) -> None:
        t = self.toks
        n = len(t)
        for k in range(n):
            w = t[k].text
            if t[k].used:
                continue
            # "x = 0.45 m", "y: 30 cm", "x of 0.4", "x coordinate 0.4"
            if w == "y" or (w == "x" and not (self.is_num(k - 1) and self.is_num(k + 1))):
                j = k + 1
                while j < n and t[j].text in ("=", ":", "of", "is", "coordinate", "position",
                                              "value", "equals", "equal", "to", "at"):  # fmt: skip
                    j += 1
                if self.is_num(j) and not (j + 1 < n and t[j + 1].text in ("x", "by")):
                    metres, end = self._metres(j, w)
                    self.coords.append((k, w, metres))
                    for m in range(k, end):
                        t[m].used = True
                    continue
            # "at (0.4, 0.3)", "at 0.4, 0.3", "position 0.4 0.3"
            if w in (
                "at",
                "position",
                "coordinates",
                "centred",
                "centered",
                "located",
                "to",
                "around",
                "near",
            ):
                j = k + 1
                if j < n and t[j].text == "(":
                    j += 1
                if self.is_num(j):
                    j2 = j + 1
                    if j2 < n and t[j2].text in lx.UNITS_M:
                        j2 += 1
                    if j2 < n and t[j2].text == ",":
                        j2 += 1
                    if self.is_num(j2):
                        x, _ = self._metres(j, "x")
                        y, end = self._metres(j2, "y")
                        if end < n and t[end].text == "," and self.is_num(end + 1):
                            end += 2
                        if end < n and t[end].text == ")":
                            end += 1
                        self.coords += [(k, "x", x), (k, "y", y)]
                        for m in range(k + 1, end):
                            t[m].used = True
                        continue
            # rotations: "rotated 45 degrees", "at an angle of 30°", "turned by 90"
            if w in ("deg", "degree", "degrees") and self.is_num(k - 1) and not t[k - 1].used:
                self.yaws.append((k, t[k - 1].value))
                t[k].used = t[k - 1].used = True
                continue
            if w in ("rotated", "rotate", "turned", "turn", "angled", "yaw", "angle", "twisted",
                     "rotation", "tilted") and not t[k].used:  # fmt: skip
                for j in range(k + 1, min(n, k + 5)):
                    if self.is_num(j) and not t[j].used:
                        self.yaws.append((k, t[j].value))
                        t[j].used = t[k].used = True
                        if self.word(j + 1) in ("deg", "degree", "degrees"):
                            t[j + 1].used = True
                        break
                    if self.word(j) == "quarter":
                        self.yaws.append((k, 90.0))
                        t[j].used = t[k].used = True
                        break
                continue
            if w in ("diagonal", "diagonally"):
                self.yaws.append((k, 45.0))
                t[k].used = True
                continue
            # axes: "along x", "along the y axis", "in the x direction", "x-axis"
            if w in ("x", "y") and not self.is_num(k - 1) and not self.is_num(k + 1):
                before = {self.word(k - 1), self.word(k - 2)}
                after = self.word(k + 1)
                if before & {
                    "along",
                    "parallel",
                    "following",
                    "in",
                    "on",
                    "direction",
                } or after in ("axis", "direction", "wise", "dir"):
                    axis = w
                    if self.word(k - 2) in ("side", "sides", "edge", "edges"):
                        # "long side along x" (the 3 of a 3 x 4 slab was laid along x, silently)
                        side = self.word(k - 3).removesuffix("est").removesuffix("er")
                        self.long_side = side in ("long", "short")
                        if side == "short":
                            axis = "y" if w == "x" else "x"
                    self.axes.append((k, axis))
                    t[k].used = True
                    if after in ("axis", "direction", "wise", "dir"):
                        t[k + 1].used = True
                    continue
            if (
                w in ("front", "back")
                and self.word(k + 1) == "to"
                and self.word(k + 2)
                in (
                    "back",
                    "front",
                )
            ):
                self.axes.append((k, self._side_axis(k, "x")))  # "front to back": an axis
                t[k].used = t[k + 1].used = t[k + 2].used = True
                continue
            across = w in ("left", "right") and self.word(k + 1) == "to"
            across = across and self.word(k + 2) in ("right", "left") and self.word(k + 2) != w
            if w in ("sideways", "lengthwise", "crosswise") or across:
                self.axes.append((k, self._side_axis(k, "y") if across else "y"))
                t[k].used = True
                if across:  # "left to right", "right to left": an axis, not a region
                    t[k + 1].used = t[k + 2].used = True
                continue
            if (w == "away" and self.word(k + 1) == "from") or (
                w == "towards" and self.word(k + 1) in ("the", "robot")
            ):
                self.axes.append((k, "x"))
                t[k].used = True
                continue
            # dimension groups: "3 x 4", "2 by 2 by 3", "3*3", "20 cm by 15 cm"
            if self.is_num(k):
                group = self._dims_at(k)
                if group is not None:
                    values, end = group
                    said_after = [self.word(m) for m in range(end, end + 3)]
                    # "5 by 5 with the inside empty": the frame's size, its inside said after
                    inner = "with" not in said_after[:2] and bool(
                        set(said_after)
                        & {
                            "space",
                            "hole",
                            "opening",
                            "interior",
                            "inside",
                            "cavity",
                            "void",
                            "gap",
                        }
                    )
                    self.dims.append((k, [v + 2 for v in values] if inner else values))
                    if inner:
                        self.notes.append(f"an inside of {' by '.join(map(str, values))} parts")
                    for m in range(k, end):
                        t[m].used = True
        # measurements with units: "20 cm tall", "a 0.3 m wall", "height of 15 cm"
        for k in range(n):
            if t[k].used or not self.is_num(k) or self.word(k + 1) not in lx.UNITS_M:
                continue
            metres = t[k].value * lx.UNITS_M[self.word(k + 1)]
            t[k].used = t[k + 1].used = True
            fieldname = None
            nxt = [self.word(k + 2), self.word(k + 3)]
            prev = [self.word(k - 1), self.word(k - 2), self.word(k - 3)]
            # a comma ends what the value is said of: "two towers of 150 mm, spaced 5 cm apart"
            nxt = nxt[: nxt.index(",")] if "," in nxt else nxt
            nxt = nxt[: nxt.index("spaced")] if "spaced" in nxt else nxt  # "spaced 5 cm apart"
            # "length 20cm, height 15cm": a dimension noun just before names this value
            named = (
                prev[0] in ("length", "height", "width", "depth") and prev[0] in lx.DIMENSION_WORDS
            )
            for w in [prev[0], *nxt, *prev[1:]] if named else nxt + prev:
                if w in lx.DIMENSION_WORDS:
                    fieldname = lx.DIMENSION_WORDS[w] + "_m"
                    break
                if w in (
                    "apart",
                    "spacing",
                    "spaced",
                    "gap",
                    "gaps",
                    "separated",
                    "between",
                    "space",
                ):
                    fieldname = "gap_m"
                    break
            behind = [j for j in (k + 2, k + 3) if self.word(j) in nxt]
            for j in (k - 1,) if named else (*behind, k - 1, k - 2, k - 3):
                if (
                    0 <= j < n
                    and t[j].text
                    in set(lx.DIMENSION_WORDS)
                    | {"apart", "spacing", "spaced", "gap", "gaps", "separated"}
                    and not t[j].used
                ):
                    t[j].used = True
                    break
            self.measures.append((k, metres, fieldname))

    def _dims_at(self, k: int) -> tuple[list[int], int] | None:
        """A group of 2–3 sizes starting at token k, each in parts or with a unit."""
        values: list[float] = []
        units: list[float | None] = []
        j = k
        counted: list[bool] = []  # "3 cubes by 20 cm": said in parts, whatever comes last
        while self.is_num(j) and not self.toks[j].used:
            values.append(self.toks[j].value)
            unit = lx.UNITS_M.get(self.word(j + 1))
            units.append(unit)
            parts_said = unit is None and self.word(j + 1) in lx.PART_WORDS and self.word(
                j + 2
            ) in ("x", "by")
            counted.append(parts_said)
            j += 2 if unit is not None or parts_said else 1
            if len(values) < 3 and self.word(j) in ("x", "by", "times", "*") and self.is_num(j + 1):
                j += 1
                continue
            break
        if len(values) < 2 or (any(counted) and all(u is None for u in units)):
            return None  # "a bay 5 cubes by 5": read by the family (a wall's length by height)
        trailing = units[-1]
        s = self.cell.cube[0]
        parts = []
        for v, unit, said in zip(values, units, counted, strict=True):
            unit = unit if unit is not None or said else trailing
            parts.append(int(v) if unit is None else max(1, round(v * unit / s)))
        if any(u is not None for u in units):
            self.notes.append(f"{' by '.join(f'{v:g}' for v in values)} read as {parts} parts")
        return parts, j

    def _verb_position(self, k: int) -> bool:
        """Token k starts a clause (imperative verb), e.g. "Pack 8 cubes…", "please stack…"."""
        return all(self.word(m) in CLAUSE_LEAD for m in range(k))

    # -- pass 2: shape nouns ---------------------------------------------------------------
    def _ambiguous_is_shape(self, k: int) -> bool:
        w = self.word(k)
        prev = self.word(k - 1)
        nxt = self.word(k + 1)
        if w in ("block", "brick", "box", "cube"):
            if prev in ("one", "1") and self.word(k - 2) in ("as", "into", "in", "form", "forming"):
                return True  # "12 cubes as one block"
            if self.is_num(k - 1) and not self.toks[k - 1].used:
                return False  # "a 3-cube tower", "1 block"
            if nxt in lx.SHAPE_WORDS and nxt not in lx.AMBIGUOUS_SHAPES:
                return False  # "block tower", "brick wall": a material
            if any(
                d[0] == k - 1 or (self.toks[k - 1].used and self.dims and d[0] < k)
                for d in self.dims
            ):
                return True
            if prev in lx.SIZE_WORDS or prev in (
                "solid",
                "single",
                "compact",
                "dense",
                "filled",
                "full",
            ):
                return True
            if nxt in (
                "of",
                "made",
                "built",
                "consisting",
                "composed",
                "from",
                "out",
                "using",
                "with",
            ):
                return True
            return w != "cube"
        if w in ("square", "squares", "rectangle"):
            if prev in ("roughly", "approximately", "about", "nearly", "almost", "fairly", "quite",
                        "very", "perfectly", "more", "less", "is", "be", "are", "inches", "inch",
                        "cm", "mm", "m", "feet", "ft"):  # fmt: skip
                return False  # "an enclosure, roughly square": a description
            return nxt not in lx.SHAPE_WORDS  # not "square pyramid", "square enclosure"
        if w == "corner":
            if (
                nxt in lx.SHAPE_WORDS
                or prev in lx.REGION_WORDS
                or prev in ("the", "each", "every", "its")
            ):
                return False
            return prev in ("a", "an", "one", "single") or prev in lx.SIZE_WORDS
        if w == "plus":
            return nxt in ("sign", "shape", "shaped", "symbol") or (
                prev in ("a", "an") and nxt in ("", "of", "with", "made")
            )
        if w == "steps":
            others = any(
                x.text in lx.SHAPE_WORDS and x.text not in lx.AMBIGUOUS_SHAPES for x in self.toks
            )
            return not (self.is_num(k - 1) and others)
        if w in ("line", "lines", "string", "strip", "track", "lane"):
            return prev in (
                "a",
                "an",
                "in",
                "one",
                "single",
                "straight",
                "long",
                "short",
            ) or self.is_num(k - 1)
        if w in (
            "layer",
            "frame",
            "outline",
            "boundary",
            "pad",
            "deck",
            "panel",
            "plate",
            "sheet",
            "field",
            "pads",
            "decks",
            "panels",
            "plates",
            "layers",
        ):
            return (
                prev in _FLAT_LEADS
                or prev in lx.SIZE_WORDS
                or (self.is_num(k - 1) and self.toks[k - 1].used)
                or (prev in lx.UNITS_M and self.toks[k - 1].used)  # "a 10 x 10 cm pad"
                or (k == 0 and self.is_num(k + 1))  # "pad 150 x 100 mm"
            )
        if w in ("group", "arrangement", "formation"):
            return prev in lx.SIZE_WORDS or prev in ("compact", "dense", "tight", "close")
        # the rest ("well", "keep", "mass", …) need an article or a size word in front
        return prev in ("a", "an", "one", "single") or prev in lx.SIZE_WORDS

    def scan_shapes(self) -> None:
        t = self.toks
        for k, tok in enumerate(t):
            if tok.used or tok.kind != "word":
                continue
            w = tok.text
            shape = None
            if w in lx.LETTER_SHAPES:
                nxt = self.word(k + 1)
                if nxt in lx.LETTER_SHAPE_TAILS or (
                    self.word(k - 1) in ("a", "an", "the", "letter", "capital", "one")
                    or self.word(k - 1) in lx.SIZE_WORDS
                    or (k == 0 and nxt in ("with", "of", ",", "arms", "legs"))  # "L w/ arms 5"
                ):
                    shape = lx.LETTER_SHAPES[w]
                    if nxt in lx.LETTER_SHAPE_TAILS:
                        t[k + 1].used = True
                    if nxt in ("shapes", "frames", "pieces", "blocks", "walls"):
                        # "two L shapes": two of them, the count is not a size
                        self.hits.append(Hit(index=k, shape=shape, plural=True, verb=False))
                        tok.used = True
                        continue
            elif w == "table" and self.word(k - 1) in ("the", "on", "of"):
                continue
            elif w in lx.SHAPE_WORDS:
                if (w in lx.AMBIGUOUS_SHAPES or w == "cube") and not self._ambiguous_is_shape(k):
                    continue
                shape = lx.SHAPE_WORDS[w]
            elif w == "cube" and self._ambiguous_is_shape(k):
                shape = "block"
            if shape is None:
                continue
            tok.used = True
            plural = w.endswith("s") and w not in (
                "stairs",
                "steps",
                "bleachers",
                "crossroads",
                "series",
                "mass",
            )
            # noun compounds: "door frame", "brick wall", "square pyramid": the last noun heads,
            # except a part of the one before ("bridge pillars 10 cm high": the bridge's own)
            if (
                self.hits
                and self.hits[-1].index == k - 1
                and self.hits[-1].shape in _ON_LEGS
                and w
                in ("pillar", "pillars", "leg", "legs", "post", "posts", "support", "supports")
            ):
                tok.used = False
                continue
            if self.hits and self.hits[-1].index == k - 1:
                self.hits.pop()
            verb = w in lx.VERB_SHAPES and self._verb_position(k)
            self.hits.append(Hit(index=k, shape=shape, plural=plural, verb=verb))
        # "hollow square/rectangle" → enclosure; "solid/filled" keep grid
        for h in self.hits:
            if (
                h.shape == "tower"
                and self.word(h.index) in ("pile", "piles", "heap")
                and (
                    self.word(h.index - 1) in ("compact", "dense", "tight", "neat", "close", "tidy")
                )
            ):
                h.shape = "pack"  # "a compact pile of 8 cubes"
            if h.shape == "grid" and (
                self.word(h.index - 1) in ("hollow", "empty", "open")
                or (len(self.hits) == 1 and self._said_hollow())
            ):
                h.shape = "enclosure"  # "a 4x4 pad, hollow": the one structure named
            if h.shape == "block" and (
                self.word(h.index - 1) in ("hollow", "empty")
                or (len(self.hits) == 1 and self._said_hollow() and self._said_hollow_middle())
            ):
                h.shape = "enclosure"  # "a box, four by four, hollow in the middle"
        # the word "cube" as a shape is one part ("a single cube") unless sized: see `build`
        for h in self.hits:
            if self.word(h.index) == "cube" and h.shape == "block":
                h.params["_cube_word"] = True

    # -- pass 3: segmentation --------------------------------------------------------------
    def segment(self) -> None:
        hits = self.hits
        n = len(self.toks)
        if not hits:
            return
        hits[0].start = 0
        hits[-1].end = n
        for a, b in itertools.pairwise(hits):
            cut = None
            for k in range(a.index + 1, b.index):
                if (
                    self.word(k) in lx.SEPARATORS
                    or self.word(k) in lx.JOIN_WORDS
                    or self.word(k) == "with"
                ):
                    cut = k
            if cut is None:
                # no conjunction: the second noun's modifiers start after the first noun's
                cut = b.index
                while cut - 1 > a.index and (
                    self.is_num(cut - 1)
                    or self.word(cut - 1) in lx.SIZE_WORDS
                    or self.word(cut - 1) in ("a", "an", "the")
                ):
                    cut -= 1
            a.end = cut
            b.start = cut

    def _names_use(self, m: int) -> bool:
        """The word at `m`, just before a shape noun, is one SDI reads nothing from ("three
        lookout towers", "two red stacks"): it does not stop a count before it (the accounting
        reports it)."""
        w = self.word(m)
        known = (lx.SHAPE_WORDS, lx.PART_WORDS, lx.DIMENSION_WORDS, lx.LEVEL_WORDS,
                 lx.STEP_WORDS, lx.SPAN_WORDS, lx.UNITS_M, lx.REGION_WORDS, lx.SIZE_WORDS,
                 lx.SEPARATORS, lx.JOIN_WORDS)  # fmt: skip
        return (
            len(w) >= 3
            and w.isalpha()
            and not self.is_num(m)
            and w not in ("and", "the", "with", "for", "more", "other", "these", "those")
            and not any(w in group for group in known)
        )

    def _side_axis(self, k: int, axis: str) -> str:
        """The axis a structure runs along when the words before "left to right" / "front to
        back" say which side runs that way: "15 cm wide (left to right)" — the width runs
        along `axis`, so the length along the other; "long side left to right" — the longer
        side along `axis`."""
        before = self.word(k - 1)
        if before in ("from", "going", "running", "measured"):  # "five across from left to right"
            k -= 1
            before = self.word(k - 1)
        if before in ("side", "sides", "edge", "edges") and self.word(k - 2) in (
            "long",
            "longer",
            "longest",
        ):
            self.long_side = True
        if before in ("wide", "deep", "across", "width", "depth") or (
            before in ("side", "sides", "edge", "edges")
            and self.word(k - 2) in ("short", "shorter", "shortest")
        ):
            return "x" if axis == "y" else "y"
        return axis

    # -- pass 4: attributes ----------------------------------------------------------------
    def attributes(self, h: Hit) -> None:
        t = self.toks
        p = h.params
        span_range = range(h.start, h.end)

        def take(k: int) -> None:
            t[k].used = True

        # dimension groups
        for k, values in self.dims:
            if k in span_range:
                self._apply_dims(h, values)
        self._value_lists(h)
        # measurements in metres
        for k, metres, fname in self.measures:
            if k in span_range:
                fname = fname or PRIMARY_M.get(h.shape, "length_m")
                word = next(
                    (self.word(j) for j in range(k, k + 4) if self.word(j) in lx.DIMENSION_WORDS),
                    "",
                )
                if word == "thick" and h.shape in ("grid", "block"):
                    fname = "height_m"  # "a slab 2 inches thick": its height, not its width
                if (fname == "gap_m" and h.shape in _ON_LEGS) or (
                    fname == "width_m" and h.shape in ("arch",)
                ):
                    p["span"] = max(1, round(metres / self.cell.cube[0]))
                else:
                    if fname in p and p[fname] != metres:
                        other = {"width_m": "length_m", "length_m": "width_m"}.get(fname)
                        said = next(
                            (
                                self.word(j)
                                for j in range(k, k + 4)
                                if self.word(j) in lx.DIMENSION_WORDS
                            ),
                            "",
                        )
                        if (
                            other == "length_m"
                            and other not in p
                            and said == "deep"
                            and h.shape in ("grid", "block", "enclosure", "castle")
                            and not any(a in span_range for a, _ in self.axes)
                        ):
                            # "10 cm wide and 20 cm deep": deep is along x (the width slot)
                            p["length_m"] = p.pop("width_m")
                        elif other and other not in p:
                            fname = other  # "15 cm wide and 25 cm deep": two different sides
                        else:
                            self.notes.append(
                                f"ignored {fname}={p[fname]:g}: two sizes for one side; "
                                f"used {metres:g}"
                            )
                    p[fname] = metres
        for k, axis in self.axes:
            if k in span_range:
                p["axis"] = axis
                a, b = p.get("length"), p.get("width")
                if self.long_side and isinstance(a, int) and isinstance(b, int):
                    p["length"], p["width"] = max(a, b), min(a, b)
        for k, yaw in self.yaws:
            if k in span_range:
                p["yaw_deg"] = yaw
        for k, axis, value in self.coords:
            if k in span_range:
                p["at_" + axis] = value

        # "N rows/layers of M": levels (walls, blocks…) or a grid's rows
        for k in span_range:
            rows = lx.LEVEL_WORDS | {"rows", "columns", "lines"}
            if (
                self.is_num(k)
                and not t[k].used
                and self.word(k + 1) in rows
                and not (k + 1 == h.index and h.shape == "tower")  # "two columns of 2": two
                and self.word(k + 2) == "of"
                and self.is_num(k + 3)
                and not t[k + 3].used
            ):
                a, b = int(t[k].value), int(t[k + 3].value)
                if h.shape in ("grid", "pack", "row"):
                    h.shape = "grid" if h.shape == "row" else h.shape
                    p.setdefault("width", a)
                    p.setdefault("length", b)
                elif h.shape == "tower":
                    p.setdefault("height", a * b)
                else:
                    p.setdefault("height", a)
                    p.setdefault("length", b)
                for m in range(k, k + 4):
                    take(m)

        for k in span_range:
            if t[k].used:
                continue
            w = t[k].text
            nxt = self.word(k + 1)
            prev, prev2 = self.word(k - 1), self.word(k - 2)
            if t[k].kind == "num":
                v = round(t[k].value)
                if v != t[k].value and abs(t[k].value) < 50:
                    self.notes.append(f"rounded {t[k].value:g} to {v}")
                if v <= 0:
                    raise SpecError(
                        f"{t[k].text} is not a usable count; counts must be whole numbers ≥ 1",
                        understood=self.understood(),
                    )
                # "N high/tall/long/wide", "N cubes high", "N levels", "N steps", "N spans"
                j = k + 1
                if self.word(j) in lx.PART_WORDS:
                    j += 1
                wj = self.word(j)
                if j == k + 1 and self._count_of_sized(k):
                    pass  # "two tall towers", "one tall tower": how many, each tall
                elif wj in lx.DIMENSION_WORDS and (wj not in ("up", "height", "width", "length")):
                    key = lx.DIMENSION_WORDS[wj]
                    if h.shape in ("u_shape", "t_shape"):  # "a U 4 wide and 3 deep"
                        key = "length" if key == "width" and wj != "deep" else key
                        key = "width" if wj in ("deep", "long", "tall", "high") else key
                        if wj in ("tall", "high") and "length" in p and "width" in p:
                            key = "height"  # "a T 5 by 3, 2 high": its courses, both sides said
                    part = next((b for b in (prev, prev2) if b in _T_PARTS), None)
                    if h.shape == "t_shape" and part:  # "the top bar 5 long and the stem 3"
                        key = _T_PARTS[part]
                        take(k - 1 if part == prev else k - 2)
                    if wj == "thick" and p.keys() & {"length", "length_m"} and p.keys() & {
                        "width", "width_m"
                    }:  # "five across and three deep, one cube thick", "30 cm long, 15 cm deep"
                        key = "height"
                    elif key in p and p[key] != v and p.get("_word_" + key) != wj:
                        other = {"width": "length", "length": "width"}.get(key)
                        if (
                            other == "length"
                            and other not in p
                            and wj == "deep"
                            and p.get("_word_width") in ("wide", "across")
                            and h.shape in ("grid", "block", "enclosure", "castle")
                            and not any(a in span_range for a, _ in self.axes)
                        ):
                            # "3 wide and 5 deep": deep is front to back (the width slot,
                            # along x), wide left to right (the length, along y)
                            p["length"], p["_word_length"] = p.pop("width"), p.pop("_word_width")
                        elif other and other not in p:
                            key = other  # "3 wide, 2 deep": two different sides
                    p.setdefault("_word_" + key, wj)
                    p.setdefault(key, v)
                    for m in range(k, j + 1):
                        take(m)
                    continue
                if (
                    wj in lx.LEVEL_WORDS
                    and j == k + 1
                    and not (wj in ("row", "rows") and h.shape in ("grid", "row"))
                ):
                    if wj == "deep":
                        p.setdefault("width", v)
                    else:
                        p.setdefault("height", v)
                    take(k)
                    take(j)
                    if self.word(j + 1) in ("high", "tall", "deep", "thick"):
                        take(j + 1)
                    continue
                if wj in lx.STEP_WORDS and j == k + 1:
                    if h.shape == "staircase":
                        p.setdefault("steps", v)
                    else:
                        p.setdefault("height", v)
                    take(k)
                    take(j)
                    continue
                if wj in lx.SPAN_WORDS and j == k + 1:
                    p.setdefault(
                        "spans"
                        if wj.endswith("s")
                        or (
                            wj in ("span",)
                            and h.shape == "bridge"
                            and v > 1
                            and prev not in ("of",)
                        )
                        else "span",
                        v,
                    )
                    take(k)
                    take(j)
                    continue
                wk = self.word(j + 1) if wj in ("at", "on", "in", "for", "along") else wj
                if wk == "the":
                    wk = self.word(j + 2)
                placed_on = wj in ("at", "on", "in", "for", "along") and wk in ("base", "bottom")
                if wk in PART_NOUN_KEYS and (wk == wj or placed_on):
                    key = PART_NOUN_KEYS[wk]
                    if key == "height" and j == k + 1:
                        key = "_legs"  # "four legs": how many, not how high
                    if key == "arms":
                        p.setdefault("length", v)
                        p.setdefault("width", v)
                    else:
                        p.setdefault(key, v)
                    last = j if wk == wj else (j + 2 if self.word(j + 1) == "the" else j + 1)
                    for m in range(k, last + 1):
                        take(m)
                    continue
                if (
                    wj in ("taller", "higher", "above", "over", "more", "extra")
                    and h.shape in ("castle", "tower")
                    and prev != "of"  # "a tower of 2 cubes above it": its height
                ):
                    if not (wj == "over" and self.word(j + 1) in _MOVED_OVER):
                        p["_relative"] = v  # (not "2 cubes over to the left": how far it moved)
                    for m in range(k, j + 1):
                        take(m)
                    continue
                if wj in ("apart", "spacing", "gap", "gaps"):
                    if h.shape in _ON_LEGS and wj != "apart":
                        p["span"] = v
                    else:
                        # "2 cubes apart", "gap 2": parts; a bare "20 apart": centimetres
                        in_parts = (
                            wj != "apart"
                            or v < 10
                            or any(self.word(m) in lx.PART_WORDS for m in range(k + 1, j))
                        )
                        p["gap_m"] = v * self.cell.cube[0] if in_parts else v / 100.0
                    take(k)
                    take(j)
                    continue
                if (
                    self.word(j) in ("on", "per") and self.word(j + 1) in ("a", "each", "every")
                ) or (
                    self.word(j) in ("per", "a", "each") and self.word(j + 1) in ("side", "edge")
                ):  # "4 cubes per side", "4 cubes a side"
                    p.setdefault("length", v)
                    p.setdefault("width", v)
                    take(k)
                    continue
                # "height of N", "length: N", "span of N", "base of N", "with N steps"
                role: str | None = None
                # "3 high and two towers": the word before "and" sizes what came before
                alone = (",", ";", ":", "and", "or", "then", "but")
                for back in (prev,) if prev in alone else (prev, prev2):
                    if back in (
                        "height",
                        "tall",
                        "high",
                        "levels",
                        "tiers",
                        "layers",
                        "storeys",
                        "floors",
                        "stories",
                    ):
                        role = "height"
                    elif back in ("length", "long"):
                        role = "length"
                    elif back in ("width", "wide", "depth", "deep", "breadth"):
                        role = "width"
                    elif back in ("span", "spanning", "opening", "gap", "spacing", "distance"):
                        role = "span" if h.shape in _ON_LEGS else "gap"
                    elif back in ("base", "bottom", "foot", "footprint"):
                        role = "length"
                    elif back in (
                        "arm",
                        "arms",
                        "side",
                        "sides",
                        "edge",
                        "edges",
                        "leg",
                        "legs",
                        "wing",
                        "wings",
                    ):
                        role = "arms"
                    elif back in ("steps", "stairs") and h.shape == "staircase":
                        role = "steps"
                    if role == "arms" and (
                        self._pillar_legs(h, back)
                        or (h.shape in _ON_LEGS and back in ("leg", "legs"))  # "bridge legs 3"
                    ):
                        role = "height"  # "bridge, legs 3": how high its legs are
                    if h.shape == "t_shape" and back in _T_PARTS:
                        role = _T_PARTS[back]  # "a T, bar 5, stem 3"
                        take(k - 1 if back == prev else k - 2)
                    if role:
                        break
                if role == "arms":
                    p.setdefault("length", v)
                    p.setdefault("width", v)
                    take(k)
                    continue
                if role == "gap":
                    p["gap_m"] = v * self.cell.cube[0] if v < 10 else v / 100.0
                    take(k)
                    continue
                if role:
                    p.setdefault(role, v)
                    take(k)
                    continue
                # a number in front of a plural shape noun: how many structures
                if (
                    k + 1 <= h.index
                    and all(
                        (self.is_num(m) and self.word(m + 1) in lx.PART_WORDS and m + 2 == h.index)
                        or (self.word(m) in lx.PART_WORDS and self.is_num(m - 1) and m > k + 1)
                        or (self.is_num(m) and self.word(m + 1) in lx.DIMENSION_WORDS)
                        or (self.word(m) in lx.DIMENSION_WORDS and self.is_num(m - 1) and m > k + 1)
                        or self.word(m) in lx.SIZE_WORDS
                        or self.word(m)
                        in (
                            "separate",
                            "individual",
                            "identical",
                            "distinct",
                            "similar",
                            "small",
                            "more",
                            "different",
                            "independent",
                            "free",
                            "standing",
                            "freestanding",
                        )
                        or (m < len(self.toks) and self.toks[m].used)  # "two 2 x 2 pads"
                        or (m + 1 == h.index and self._names_use(m))  # "three lookout towers"
                        for m in range(k + 1, min(h.index + 1, len(self.toks)))
                    )
                    and h.plural
                ):
                    h.multiplicity = v
                    take(k)
                    continue
                if v == 1 and not h.plural and (
                    k + 1 == h.index or lx.SHAPE_WORDS.get(self.word(k + 1)) == h.shape
                ):
                    # "1 tower", "one tower", "one block 3 by 3 by 2" (its sizes after it):
                    # one structure, not one part
                    take(k)
                    if k + 1 != h.index:
                        take(k + 1)
                    continue
                if (
                    self.word(k + 1) in lx.PART_WORDS
                    or prev in ("of", "with", "using", "from", "has", "have")
                    or k + 1 == h.index
                ):
                    p.setdefault("_count", v)
                    take(k)
                    if self.word(k + 1) in lx.PART_WORDS:
                        take(k + 1)
                        if self.word(k + 2) not in lx.SHAPE_WORDS:  # not "2-cube pillars"
                            p["_parts_said"] = True  # "of 6 cubes": parts, not a height
                    continue
                p.setdefault("_loose", []).append(v)
                take(k)
                continue
            # words
            if w in QUANTITY_WORDS and (
                nxt in ("of",)
                or self.is_num(k + 1)
                or nxt in lx.PART_WORDS
                or nxt in lx.SHAPE_WORDS
                or k + 1 == h.index
                or nxt in lx.SIZE_WORDS
            ):
                q = QUANTITY_WORDS[w]
                if (
                    k < h.index
                    and h.plural
                    and (
                        nxt in lx.SHAPE_WORDS
                        or (nxt == "of" and self.word(k + 2) in lx.SHAPE_WORDS)
                        or all(
                            self.word(m) in lx.SIZE_WORDS
                            or self.word(m) in ("of", "separate", "individual")
                            or self.is_num(m)
                            or self.word(m) in lx.DIMENSION_WORDS
                            or self.word(m) in lx.PART_WORDS
                            for m in range(k + 1, h.index)
                        )
                    )
                ):
                    h.multiplicity = q
                else:
                    p.setdefault("_count", q)
                take(k)
                continue
            if w in ("thin", "skinny", "slim", "narrow", "slender") and h.shape in (
                "tower",
                "wall",
                "row",
            ):
                take(k)  # a tower is one part wide anyway
                continue
            if w in ("low", "flat", "squat") and h.shape in ("grid", "row", "pack"):
                take(k)  # "a low, wide platform": a grid is one layer anyway
                continue
            if w in lx.SIZE_WORDS:
                dim, size = lx.SIZE_WORDS[w]
                if (
                    w in ("high", "tall", "long", "wide", "deep")
                    and self.is_num(k - 1)
                    and not self._count_of_sized(k - 1)
                ):
                    continue
                p.setdefault("_sizes", []).append((dim, size))
                take(k)
                continue
            if w in lx.REGION_WORDS:
                region = lx.REGION_WORDS[w]
                if (
                    w in ("close", "near")
                    and nxt == "to"
                    and self.word(k + 2) == "the"
                    and self.word(k + 3) in ("back", "left", "right", "front", "rear", "edge")
                ):
                    take(k)  # "close to the back": the back, said after it
                    continue
                if w in ("close", "near") and (
                    nxt in ("together", "each")
                    or (nxt == "to" and "other" in (self.word(k + 3), self.word(k + 4)))
                    or (nxt == "to" and self.word(k + 3) == "another")
                ):
                    continue  # "close together", "near each other": how far apart, not where
                if (
                    w == "far"
                    and nxt in ("left", "right")
                    and self.word(k + 2) not in ("corner", "corners", "back", "front")
                ):
                    take(k)  # "at the far left": all the way to the left, not the back
                    continue
                if (
                    w in ("far", "close", "near")
                    and nxt in ("from", "to")
                    and self.word(k + 2) in ("the", "robot")
                ):
                    region = "back" if w == "far" else "front"
                if (w == "left" and prev == "to" and prev2 == "right") or (
                    w == "right" and nxt == "to"
                ):
                    continue
                p.setdefault("_regions", []).append(region)
                take(k)
                continue
            if w == "corner" and prev in ("the", "a", "one", "any"):
                p.setdefault("_regions", []).append("corner")
                take(k)
                continue
            sides = [self.word(j) for j in (k - 1, k - 2) if self.word(j) in _SIDES]
            if (
                w in ("edge", "edges", "boundary", "border")
                and sides
                and "from" not in (self.word(k - 3), self.word(k - 4))
            ):
                # "along the back edge", "hugging the right boundary": against that side
                p.setdefault("_edges", []).append(sides[0])
                take(k)
                continue
            if w in (
                "apart",
                "spaced",
                "separated",
                "gaps",
                "gapped",
                "spread",
                "scattered",
                "distributed",
                "sparse",
                "sparsely",
                "loosely",
                "gap",
            ):
                p.setdefault("gap_m", self.cell.cube[0])
                take(k)
                continue
            if w in ("d", "dimensional", "dimension") and self.is_num(k - 1):
                p["dims"] = 3 if t[k - 1].value >= 3 else 2
                take(k)
                take(k - 1)
                continue
            if h.shape == "pyramid" and w in (
                "square",
                "stepped",
                "ziggurat",
                "solid",
                "four",
                "sided",
                "volumetric",
                "full",
                "egyptian",
                "mayan",
                "aztec",
                "pyramidal",
            ):
                p["dims"] = 3
                take(k)
                continue
            if h.shape == "pyramid" and w in ("flat", "triangular", "planar", "triangle", "2d"):
                p["dims"] = 2
                take(k)
                continue
            if w in lx.BEAM_WORDS and (
                prev in ("of", "from", "using", "with")
                or nxt in lx.SHAPE_WORDS
                or (w.endswith("s") and k < h.index)
            ):
                self.beam = True  # "a wall of beams", "a beam tower": made of beams
                take(k)
        if self.word(h.index) in ("ziggurat", "ziggurats"):
            p.setdefault("dims", 3)

    def _value_lists(self, h: Hit) -> None:
        """ "three towers of 2, 3 and 4 cubes": one value per copy."""
        t = self.toks
        k = h.start
        while k < h.end:
            if not self.is_num(k) or t[k].used:
                k += 1
                continue
            run, j = [k], k + 1
            while (
                self.word(j) in (",", "and", "or")
                and self.is_num(j + 1)
                and not t[j + 1].used
                and self.word(j + 2) not in lx.SHAPE_WORDS  # "… of 3 and one tower of 5"
                and not (self.word(j + 1) in ("one", "1") and self.word(j + 2) in ("of", "with"))
            ):
                run.append(j + 1)
                j += 2
                if self.word(j) == "and" and self.word(j - 2) == ",":
                    continue
            if (
                len(run) == 2
                and self.word(run[0] + 1) == ","
                and self.word(run[1] + 1) in _SECOND_SIZE
                and h.multiplicity <= 1
                and not h.plural
            ):  # "a pyramid with a base of 4, 3 levels high": two sizes of one structure
                k += 1
                continue
            if len(run) >= 2:
                h.params["_each"] = [round(t[m].value) for m in run]
                for m in range(k, j):
                    t[m].used = True
                after = j
                if self.word(after) in lx.PART_WORDS:
                    t[after].used = True
                    after += 1
                listed = any(self.word(m + 1) in ("and", "or") for m in run[:-1])
                if listed and self.word(after) in _LISTED_SIZE.get(h.shape, ()):
                    t[after].used = True
            k = j

    def _apply_dims(self, h: Hit, values: list[int]) -> None:
        p = h.params
        if h.shape == "pyramid":
            p["length"] = values[0]
            if len(values) >= 2 and values[1] == values[0]:
                p["dims"] = 3
            if len(values) == 3:
                p["height"] = values[2]
            return
        if h.shape == "wall":
            p["length"] = values[0]
            if len(values) == 2:
                p["height"] = values[1]
            else:
                p["width"], p["height"] = values[1], values[2]
                h.shape = "block" if values[1] > 1 else "wall"
            return
        if h.shape in ("tower", "row") and len(values) >= 2:
            h.shape = "block" if len(values) == 3 or h.shape == "tower" else "grid"
        if h.shape in ("pack",) and len(values) >= 2:
            h.shape = "block" if len(values) == 3 else "grid"
        if h.shape == "grid" and len(values) == 3:
            h.shape = "block"
        if h.shape == "block" and len(values) == 2:
            p["_flat"] = True  # "a 3 by 3 block": one level unless levels are given
        keys = ["length", "width", "height"]
        for key, v in zip(keys, values, strict=False):
            p[key] = v

    # -- compounds and defaults ----------------------------------------------------------------
    def merge_compounds(self) -> None:
        self._merge_definites()
        # "three towers in a row", "towers in a line": an arrangement, not another structure
        self.hits = [
            h
            for n, h in enumerate(self.hits)
            if not (
                n > 0
                and h.shape == "row"
                and not set(h.params) - {"axis"}  # "in a line from left to right": the order
                and self.word(h.index - 1) in ("a", "one", "single", "straight")
                and self.word(h.index - 2) in ("in", "into", "along", "forming", "form")
            )
        ]
        hits = self.hits
        merged: list[Hit] = []
        k = 0
        while k < len(hits):
            h = hits[k]
            nxt = hits[k + 1] if k + 1 < len(hits) else None
            between = self.between(h, nxt)
            # "two towers joined by a bridge", "towers connected with a beam"
            if (
                nxt
                and h.shape == "tower"
                and nxt.shape == "bridge"
                and (h.plural or h.multiplicity > 1)
                and between & (lx.JOIN_WORDS | {"by"})
            ):
                nxt.params = {**nxt.params, **h.params}
                nxt.params.setdefault("spans", max(1, h.multiplicity - 1))
                if "height" not in h.params and "_count" in h.params:
                    nxt.params["height"] = nxt.params.pop("_count")
                nxt.multiplicity = 1
                nxt.start = h.start
                hits[k + 1] = nxt
                k += 1
                continue
            # "pack 8 cubes into a compact cube", "stack 6 cubes as a pyramid": the verb's
            # shape gives way to the target named after it
            if nxt and h.verb and (
                between & {"into", "as", "forming", "form", "to"}
                or (not nxt.verb and between <= {"a", "an", "the", "one", "single", "some",
                                                  "solid"})
            ):  # "stack a solid lump three by three by two": the lump, stacked
                for key, value in h.params.items():
                    nxt.params.setdefault(key, value)
                nxt.start = h.start
                k += 1
                continue
            # containers absorb their components: "a castle: a 4 by 4 ring of walls with a
            # tower at each corner", "a shelter with four legs and a roof", "a bridge with
            # three spans on pillars 3 high", "a courtyard with walls 2 high"
            parts = COMPONENTS.get(h.shape, set())
            regional = bool(between & set(lx.REGION_WORDS)) and "and" in between
            listed = (  # "an arch, a tower in front of it": another structure, listed
                nxt is not None
                and h.shape in _ON_LEGS
                and between <= {",", "and", "a", "an", "one"}
                and bool(between & {"a", "an", "one"})
                and not nxt.plural
            )
            # "castle 5x5 walls 2 high corner towers 4": a castle's parts said without a link
            bare = h.shape == "castle" and all(w.isdigit() or w in _SIZE_TOKENS for w in between)
            linked = bool(between & LINKS) or bare
            if nxt and nxt.shape in parts and linked and not regional and not listed:
                j = k + 1
                while j < len(hits) and hits[j].shape in parts:
                    if j > k + 1 and self.between(hits[j - 1], hits[j]) & {
                        "next",
                        "beside",
                        "another",
                    }:
                        break
                    self.absorb(h, hits[j])
                    h.end = hits[j].end
                    j += 1
                merged.append(h)
                k = j
                continue
            # "a podium with four steps", "a U shaped wall": one structure named twice
            if (
                nxt
                and (nxt.shape == h.shape or self._letter_wall(h, nxt))
                and not between & (lx.SEPARATORS | {"next", "beside"})
                and not nxt.plural
                and not (
                    (h.plural or self._sized_apart(h, nxt))
                    and "with" in between
                    and self.word(nxt.index - 1) in ("a", "an", "one", "another", "single")
                )
            ):
                for key, value in nxt.params.items():
                    h.params.setdefault(key, value)
                h.end = nxt.end
                merged.append(h)
                k += 2
                continue
            merged.append(h)
            k += 1
        self.hits = merged

    def _merge_definites(self) -> None:
        """ "a T and a cross next to each other, the T on the left": "the T" is the T named
        before (one of its family, singular), so its words go to that one."""
        kept: list[Hit] = []
        for h in self.hits:
            same = [e for e in kept if e.shape == h.shape]
            if (
                self.word(h.index - 1) == "the"
                and not h.plural
                and len(same) == 1
                and not same[0].plural
                and same[0].multiplicity == 1
                and all(same[0].params.get(key, v) == v for key, v in h.params.items())
            ):
                same[0].params = {**same[0].params, **h.params}
                self.notes.append(
                    f"'the {self.word(h.index)}': the {h.shape.replace('_', ' ')} named before"
                )
                continue
            kept.append(h)
        self.hits = kept

    @staticmethod
    def _sized_apart(h: Hit, nxt: Hit) -> bool:
        """ "a tower of 4 with a tower of 2 on its left": each has a size of its own that the
        other's contradicts, so they are two structures, not one named twice."""
        return any(
            not key.startswith("_loose") and key in h.params and h.params[key] != value
            for key, value in nxt.params.items()
        )

    @staticmethod
    def _letter_wall(h: Hit, nxt: Hit) -> bool:
        """ "a U shaped wall": the letter names the shape, the noun the material."""
        return h.shape in LETTER_HEADS and nxt.shape in ("wall", "row")

    def between(self, a: Hit, b: Hit | None) -> set[str]:
        return {self.word(m) for m in range(a.index + 1, b.index)} if b else set()

    def _pillar_legs(self, h: Hit, word: str) -> bool:
        """ "bridge, legs 3": the legs named are a bridge's, arch's or canopy's pillars."""
        return (
            word in ("leg", "legs")
            and h.shape == "tower"
            and self.word(h.index) in ("leg", "legs")
            and any(x.shape in _ON_LEGS and x.index < h.index for x in self.hits)
        )

    def absorb(self, container: Hit, part: Hit) -> None:
        """Fold a component noun's attributes into its container."""
        cp, pp = container.params, dict(part.params)
        height = pp.pop("height", None) or pp.pop("_count", None)
        if height is None and pp.get("_loose"):
            height = pp["_loose"][0]
        pp.pop("_loose", None)
        if part.shape == "tower":
            if container.shape == "castle":
                if height is not None:
                    cp["_tower_height"] = height
            elif height is not None:
                cp.setdefault("height", height)
            elif "height_m" in pp:
                cp.setdefault("height_m", pp.pop("height_m"))
            if container.shape == "bridge" and part.multiplicity > 2:
                cp.setdefault("spans", part.multiplicity - 1)
        elif part.shape in ("wall", "enclosure", "row"):
            if height is not None and part.shape != "row":
                cp.setdefault("height", height)
            for key in ("length", "width", "length_m", "width_m"):
                if key in pp and container.shape in ("castle", "enclosure"):
                    cp.setdefault(key, pp[key])
        pp.pop("length", None)
        pp.pop("width", None)
        pp.pop("_sizes", None)
        for key, value in pp.items():
            cp.setdefault(key, value)

    def build(self, h: Hit) -> list[StructureDraft]:
        for key, kept, other in getattr(h.params, "conflicts", []):
            if key == "_count" and min(kept, other) <= 1:
                continue  # "a single cube", "one of": an article, not a count
            name = "parts" if key == "_count" else key
            self.notes.append(
                f"ignored {name} {other:g}: the command also says {name} {kept:g} for the "
                f"{h.shape}; used {kept:g}"
            )
        p = dict(h.params)
        shape = h.shape
        # "a really tall tower, the tallest you can": the utmost wins over a vague size
        sizes = sorted(p.pop("_sizes", []), key=lambda said: said[1] != "X")
        regions = p.pop("_regions", [])
        edges = p.pop("_edges", [])
        count = p.pop("_count", None)
        parts_said = p.pop("_parts_said", False)
        if parts_said and shape in _ON_LEGS and count:
            # "a bridge of 6 cubes", "a table, 6 cubes in all": its parts follow from its legs
            # and top; the count was read as their height (12 + parts), silently
            self.notes.append(
                f"ignored {count:g} parts: the {_FAMILY_WORD.get(shape, shape)}'s parts follow "
                "from its legs and top; say how high its legs are"
            )
            count = None
        loose = p.pop("_loose", [])
        tower_height = p.pop("_tower_height", None)
        relative = p.pop("_relative", None)
        each = p.pop("_each", None)
        cube_word = p.pop("_cube_word", False)
        flat = p.pop("_flat", False)
        p.pop("_tower_sizes", None)
        if (
            h.verb
            and shape == "tower"
            and not sizes
            and not any(k in p for k in ("height", "height_m", "count"))
            and self.word(h.index + 1) in ("a", "an", "another", "one", "single")
            and self.word(h.index + 2) in ("cube", "block", "part", "brick", "piece")
        ):
            p["height"] = 1  # "stack another cube on it": one cube, not a default tower
        legs = p.pop("_legs", None)
        if legs is not None and not (shape == "canopy" and legs == 4) and not (
            shape in ("bridge", "arch") and legs == 2  # "a bench: two legs and a beam on top"
        ):
            self.notes.append(
                f"ignored '{legs} legs': a {shape} has "
                + ("four legs" if shape == "canopy" else "no legs to count")
            )
        sized = (
            count is not None
            or sizes
            or loose
            or each
            or any(
                key in p for key in ("length", "width", "height", "count", "length_m", "height_m")
            )
        )
        if cube_word and not sized:
            shape, p["height"] = "tower", 1  # "a cube", "a single cube": one part
        if count is not None and shape in ("tower", "row"):
            key = PRIMARY[shape]
            if key in p and p[key] != count:
                self.notes.append(
                    f"ignored {count:g} parts: the command also says {key} {p[key]:g} for the "
                    f"{shape}; used {p[key]:g}"
                )
        if count is not None:
            key = PRIMARY[shape]
            if shape == "staircase" and "steps" not in p and (count > 6 or parts_said):
                # "a staircase of 10 cubes": the steps whose triangle holds that many
                steps = int(((8 * count + 1) ** 0.5 - 1) / 2)
                p["steps"] = max(1, steps)
                used = p["steps"] * (p["steps"] + 1) // 2
                self.notes.append(
                    f"{count} parts make a staircase of {p['steps']} steps"
                    if used == count
                    else f"ignored {count} parts: no staircase has exactly that many; built "
                    f"{p['steps']} steps ({used} parts)"
                )
            elif shape == "pyramid" and "length" not in p and count > 4:
                levels = p.get("height")
                if levels and "dims" not in p and _pyramid_parts(levels, True) == count != (
                    _pyramid_parts(levels, False)
                ):  # "a pyramid of 2 levels using 5 cubes": 4 and 1, the whole 3-D one
                    p["dims"] = 3
                p["length"] = _pyramid_base(count, p.get("dims") == 3, levels)
                used = _pyramid_parts(p["length"], p.get("dims") == 3, levels)
                if used == count:
                    self.notes.append(f"{count} parts read as a pyramid with a base of "
                                      f"{p['length']}")  # fmt: skip
                elif levels:  # "a 3-level pyramid using 10 cubes": no base gives both
                    del p["length"]
                    self.notes.append(
                        f"ignored {count} parts: no pyramid of {levels} levels has exactly "
                        f"that many"
                    )
                else:
                    self.notes.append(
                        f"ignored {count} parts: no pyramid has exactly that many; built a "
                        f"base of {p['length']} ({used} parts)"
                    )
            elif shape in ("wall",) and "length" not in p:
                p["count"] = count
            elif shape == "wall":
                # "a wall of 18 cubes, 6 long": the courses its parts make
                length, height = p["length"], p.get("height")
                if height is None and isinstance(length, int) and count % length == 0:
                    p["height"] = int(count // length)
                    self.notes.append(
                        f"{count:g} parts in courses of {length}: height {p['height']}"
                    )
                elif height is None or length * height != count:
                    self.notes.append(
                        f"ignored {count:g} parts: a wall {length} long"
                        + (f" and {height} high" if height else "")
                        + " does not have that many"
                    )
            elif shape in (
                "grid",
                "block",
                "pack",
                "row",
                "tower",
                "enclosure",
                "castle",
                "l_shape",
                "u_shape",
                "t_shape",
                "cross",
            ):
                if shape in ("enclosure", "castle") and "length" not in p:
                    side = max(3, (count + 4) // 4)
                    p["length"] = p["width"] = side
                    self.notes.append(f"{count} parts read as an enclosure {side} parts on a side")
                elif shape in ("l_shape",) and "length" not in p:
                    p["length"] = p["width"] = max(2, (count + 1) // 2)
                elif shape in ("u_shape",) and "length" not in p:
                    p["length"] = max(3, count // 3)
                    p["width"] = max(2, (count - p["length"]) // 2 + 1)
                elif shape in ("t_shape", "cross") and "length" not in p:
                    p["length"] = max(3, (count + 1) // 2 | 1)
                    p["width"] = max(2, count - p["length"] + 1)
                elif shape == "block" and "length" not in p:
                    shape = "pack"
                    p["count"] = count
                elif shape == "block":
                    p["count"] = count
                elif shape == "tower" and "height" not in p:
                    p["height"] = count
                elif shape == "row" and "length" not in p:
                    p["length"] = count
                elif shape in ("grid", "pack") and "count" not in p and "length" not in p:
                    p["count"] = count
            elif key not in p:
                p[key] = count
        for v in loose:
            key = PRIMARY[shape]
            if key == "count" and ("length" in p or "count" in p):
                continue
            if key not in p:
                p[key] = v
        for dim, size in sizes:
            if size == "X":  # "the tallest tower you can": as many levels as the cell holds
                if dim in ("height", "all") and "height" not in p:
                    p["height" if shape != "staircase" else "steps"] = int(
                        (self.cell.workspace.z_max - self.cell.workspace.z_min) / self.cell.cube[2]
                        + 1e-9
                    )
                size = "L"
            index = "SML".index(size)
            table = SIZE_TABLE.get(shape, {})
            related = {
                "length": {"length", "steps", "count", "spans"},
                "height": {"height", "steps"},
                "width": {"width"},
            }.get(dim, set())
            if dim == "width" and shape == "arch":
                # "a wide arch", "make it wider": an arch has one opening, its width fixed
                self.notes.append("ignored a width for the arch: its opening is one size")
                continue
            if dim == "width" and shape in ("wall", "row"):
                dim = "length"  # "a wide wall": walls and rows are one part thick
                related = {"length", "steps", "count", "spans"}
            if dim != "all" and not related & set(table):
                dim = "all"  # "a short row", "a long tower": the size word applies overall
            for key, values in table.items():
                applies = dim == "all" or key == dim or key in related
                wide = p.get("width", 0)
                if shape in ("wall", "row") and key == "length" and wide > values[index]:
                    continue  # "a little wall, 5 wide": its length said as its width
                if shape in ("wall", "row") and key == "length" and "count" in p:
                    # "a long wall, 10 cubes, two high", "a long one of 6 cubes": the cubes
                    # counted run its length (it was 6 long, the vague size, silently)
                    p["length"] = p.pop("count")
                    continue
                if applies and key not in p and f"{key}_m" not in p:
                    # a small block is still a block (2 high); only a low one is one layer
                    low = shape == "block" and key == "height" and dim == "all"
                    p[key] = max(values[index], 2) if low else values[index]
                    if shape == "pyramid" and key == "length" and p.get("height", 0) > p[key]:
                        # "a little pyramid, three levels": the levels said need a wider base
                        p[key] = levels = p["height"]
                        self.notes.append(f"a pyramid of {levels} levels said small: a base of "
                                          f"{levels}, the least those levels need")  # fmt: skip
        if shape == "block" and cube_word and "length" in p:
            p.setdefault("width", p["length"])  # "a compact cube of cubes": equal sides
            p.setdefault("height", p["length"])
        if shape == "block" and flat and "height" not in p and "height_m" not in p:
            p["height"] = 1
        if shape == "castle" and relative is not None:
            p["count"] = int(relative)
        elif relative is not None:
            self.notes.append(f"ignored '{relative:g} more': a {shape} has no part above another "
                              "to size; say how high it is")  # fmt: skip
        elif shape == "castle" and tower_height is not None:
            p["count"] = max(1, int(tower_height) - int(p.get("height", 1)))
        if shape in ("wall", "row") and "width" in p and "length" not in p:
            p["length"] = p.pop("width")  # a wall or a row is one part thick: "wide" is long
        if (
            shape in ("grid", "block", "enclosure", "castle")
            and "width" in p
            and "length" not in p
            and count is None
        ):
            p["length"] = p["width"]  # one side given: make it square
        region = _region(regions)
        if region:
            p["region"] = region
            names = set(regions)
            if "corner" in names and not (names & {"front", "back"} and names & {"left", "right"}):
                # "in the corner": which one was not said
                self.notes.append(f"read 'the corner' as the {region} corner (which was not said)")
        if edges:
            p["edge"] = tuple(dict.fromkeys(edges))
        if self.beam and shape in ("tower", "row", "grid", "wall"):
            p["part"] = "beam"
        kwargs = {k: v for k, v in p.items() if k in StructureDraft.model_fields}
        try:
            spec = StructureDraft(shape=shape, **kwargs)
        except ValidationError as exc:
            first = exc.errors()[0]
            raise SpecError(
                f"{shape}: {'.'.join(str(x) for x in first['loc'])} {first['msg']}",
                understood=self.understood(),
            ) from None
        copies = max(1, h.multiplicity)
        if each is not None and copies == 1:
            copies = len(each) if h.plural else 1
        if each is not None and copies == len(each):
            key = PRIMARY[shape] if PRIMARY[shape] != "count" else "length"
            return [spec.model_copy(update={key: v}) for v in each]
        if (
            each is not None
            and len(each) == 2
            and shape in ("l_shape", "u_shape", "t_shape", "grid", "enclosure")
            and spec.length is None
            and spec.width is None
        ):  # "an L with arms 4 and 3": one value per side
            return [spec.model_copy(update={"length": each[0], "width": each[1]})]
        if each is not None:
            key = PRIMARY[shape] if PRIMARY[shape] != "count" else "length"
            if getattr(spec, key, None) is None:
                spec = spec.model_copy(update={key: each[0]})
            if any(v != each[0] for v in each[1:]):
                self.notes.append(
                    f"ignored values {each[1:]}: one {shape} takes one value; used {each[0]}"
                )
        if copies > 20:
            raise SpecError(
                f"{copies} separate {shape}s is more than 20", understood=self.understood()
            )
        return [spec] * copies

    def understood(self) -> dict[str, object]:
        out: dict[str, object] = {}
        if self.hits:
            out["structures"] = [h.shape for h in self.hits]
        nums = [t.value for t in self.toks if t.kind == "num"]
        if nums:
            out["numbers"] = [int(v) if v == int(v) else v for v in nums]
        if self.coords:
            out["coordinates"] = {axis: v for _, axis, v in self.coords}
        parts = [t.text for t in self.toks if t.text in lx.PART_WORDS]
        if parts:
            out["parts"] = parts
        regions = [lx.REGION_WORDS[t.text] for t in self.toks if t.text in lx.REGION_WORDS]
        if regions:
            out["regions"] = regions
        return out

    def implied(self) -> Hit | None:
        """No shape noun: a verb ("stack five cubes") or a bare count ("place 4 cubes")."""
        if self.dims:
            shape = "block" if any(len(v) == 3 for _, v in self.dims) else "grid"
            return Hit(index=len(self.toks), shape=shape, plural=False, start=0, end=len(self.toks))
        for word, shape in IMPLYING_WORDS.items():
            if any(t.text == word for t in self.toks):
                return Hit(
                    index=len(self.toks), shape=shape, plural=False, start=0, end=len(self.toks)
                )
        counted = any(
            t.kind == "num" or t.text in QUANTITY_WORDS or t.text in lx.PART_WORDS
            for t in self.toks
        )
        for k, t in enumerate(self.toks):
            if t.text in lx.VERB_SHAPES and not t.used and (counted or self._verb_position(k)):
                # "group them", "stack 5 cubes"; not "the group meeting moved"
                t.used = True
                return Hit(
                    index=k, shape=lx.VERB_SHAPES[t.text], plural=False, start=0, end=len(self.toks)
                )
        has_part = any(t.text in lx.PART_WORDS for t in self.toks)
        has_num = any(t.kind == "num" or t.text in QUANTITY_WORDS for t in self.toks)
        said = {t.text for t in self.toks}
        if has_part and has_num and len(said & {"wide", "deep", "long", "across"}) >= 2:
            # "a single layer of cubes 4 wide and 3 deep": two sides said, a slab
            self.notes.append("no structure named: parts given two sides make a slab")
            n = len(self.toks)
            return Hit(index=n, shape="grid", plural=False, start=0, end=n)
        if has_part and (has_num or self.coords):
            self.notes.append("no structure named: placed the parts in a row")
            hit = Hit(index=len(self.toks), shape="row", plural=False, start=0, end=len(self.toks))
            for t in self.toks:
                if (
                    t.kind == "num"
                    and not t.used
                    and any(x.text in ("apart", "separate", "separately") for x in self.toks)
                ):
                    break
            return hit
        return None

    def _said_hollow(self) -> bool:
        return any(
            t.text == "hollow" and self.word(j - 1) not in ("not", "no")
            for j, t in enumerate(self.toks)
        )

    def _said_hollow_middle(self) -> bool:
        """ "hollow in the middle", "hollow inside": its middle left out (not a hollow block's
        own inside, which SDI cannot build)."""
        return any(
            t.text == "hollow"
            and (self.word(j + 1) in ("inside", "within")
                 or (self.word(j + 1) in ("in", "at") and self.word(j + 3) in ("middle", "centre",
                                                                           "center")))
            for j, t in enumerate(self.toks)
        )  # fmt: skip

    def parse(self) -> SpecDraft:
        if not self.toks:
            raise SpecError("the command is empty; say what to build, e.g. 'a 3-cube tower'")
        self.scan_geometry()
        self.scan_shapes()
        if not self.hits:
            hit = self.implied()
            if hit is None:
                known = ", ".join(sorted({s for s in lx.SHAPE_WORDS.values()}))
                raise SpecError(
                    "no structure recognised in the command; name one of: "
                    + known
                    + " (e.g. 'a tower of 4 cubes', 'a 3 by 3 grid on the left')",
                    understood=self.understood(),
                )
            if hit.shape == "grid" and self._said_hollow():  # "a hollow pad 3 by 3": by its size
                hit.shape = "enclosure"
            self.hits = [hit]
        self.segment()
        for h in self.hits:
            self.attributes(h)
        self.merge_compounds()
        # Coordinates and regions that fell outside every segment go to the only structure.
        structures: list[StructureDraft] = []
        for h in self.hits:
            structures.extend(self.build(h))
        total = len(structures)
        if total > 50:
            raise SpecError(f"{total} structures is more than 50", understood=self.understood())
        return SpecDraft(structures=tuple(structures), notes=tuple(dict.fromkeys(self.notes)))


def _pyramid_parts(base: int, three_d: bool, levels: int | None = None) -> int:
    """The parts of a pyramid on that base, of that many levels (all of them unsaid)."""
    return sum((base - k) ** (2 if three_d else 1) for k in range(min(base, levels or base)))


def _pyramid_base(count: int, three_d: bool, levels: int | None = None) -> int:
    """The smallest base whose pyramid (of that many levels) has at least `count` parts."""
    base = max(1, levels or 1)
    while _pyramid_parts(base, three_d, levels) < count:
        base += 1
    return base


def _region(regions: list[str]) -> str | None:
    if not regions:
        return None
    names = set(regions)
    depth = next((r for r in ("front", "back") if r in names), None)
    side = next((r for r in ("left", "right") if r in names), None)
    if depth and side:
        return f"{depth} {side}"
    if "corner" in names:
        return f"{depth or 'back'} {side or 'left'}"
    return depth or side or ("centre" if "centre" in names else None)


def parse_phrase(text: str, cell: CellConfig) -> tuple[SpecDraft, list[str]]:
    """Slot filling for one phrase of a command: its `SpecDraft` and the words it left unused.

    The language front end (`sdi.language`: `clauses`, `markers`) cuts a command into clauses
    and phrases and relates them; each phrase is read here. Raises `SpecError` when the phrase
    names no structure.
    """
    parser = _Parser(text, cell)
    spec = parser.parse()
    return spec, [t.text for t in parser.toks if not t.used]
