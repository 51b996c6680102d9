"""The reading in progress: the noun phrases found in a command, the relations between them,
and the account (notes, ignored and material words) that every stage adds to."""

from __future__ import annotations

from dataclasses import dataclass, field

from sdi.model.cell import CellConfig
from sdi.spec.structure_spec import SpecDraft


@dataclass
class Phrase:
    """A noun phrase that names one or more structures (or refers to earlier ones)."""

    tokens: list[int]
    clause: int
    text: str = ""
    spec: SpecDraft | None = None
    first: int = 0  # index of its first structure in the reading
    count: int = 0  # how many structures it produced
    ref: int | None = None  # a pure reference: the phrase it refers to
    side: str | None = None  # "it on the right": the side the reference names
    modified: bool = False  # "then add two more cubes to it": changed an earlier structure
    undone: bool = False  # "… Undo the last one.": its structures were taken back
    structure: int | None = None  # "the first one", "the smaller one": which structure
    beside: str | None = None  # "a tower of 5 to its right": the side of the one before it
    unused: list[str] = field(default_factory=list)


@dataclass
class PhraseRelation:
    """A relation marker between two phrases, before the phrases are structures."""

    kind: str
    subject: int  # phrase index
    object: int | None  # phrase index; None: "on top" with no object (the phrase before)
    side: str | None = None
    plural: bool = False  # "… with a wall behind them": the object's structures, all together


@dataclass
class ReadState:
    """The account every stage adds to, and the flags the rewrites set."""

    command: str
    cell: CellConfig
    notes: list[str] = field(default_factory=list)
    ignored: list[str] = field(default_factory=list)
    material: list[str] = field(default_factory=list)
    no_stack: bool = False
    no_beams: bool = False
    # "…, both 3 high", "both 3 long 2 high": every structure's size, one entry per dimension
    shared: list[tuple[str, int, str]] = field(default_factory=list)
    gap_m: float | None = None  # "one cube gap", "10 cm apart": between the structures
    gap_said: str | None = None  # the words of that gap
    gap_first: bool = False  # said before any "between" or "in the middle"
    flanked: bool = False  # a structure was placed between two others
    # "one shorter", "twice as tall": the comparisons read, as (the words, the size they gave)
    compared: list[tuple[str, int]] = field(default_factory=list)
    # "turn it so the long side runs left to right": (long|short, the axis it runs along, words)
    long_side: tuple[str, str, str] | None = None
    u_opening: tuple[str, str] | None = None  # "a U opening to the back": (side, the words)
    span_m: float | None = None  # "pillars 10 cm apart": between a bridge's own supports
    line: str | None = None  # "three towers in a line front to back": the axis they stand along
    # "four towers in a square", "in two rows of three": (rows, columns), or 0 for each when
    # only the shape was said, with the words said
    grid: tuple[int, int, str] | None = None
    triangle: str | None = None  # "three towers in a triangle": the words said
    # "with the tallest one in the middle": (what was said, "max" | "min", middle|left|right)
    order: tuple[str, str, str] | None = None
    # "a tower at its low end", "at its foot", "at its high end": beside that end of a staircase
    stair_end: str | None = None
    distinct: str | None = None  # "none of them the same height": what was said
    listing: str | None = None  # "left to right: a, then b": the order structures are named in
    # "on each corner", "at both ends": (relation kind, anchor) for the next such relation
    anchors: list[tuple[str, str]] = field(default_factory=list)
    flanking: bool = False  # "a tower on either side of it": beside it, apart, not against it
    region_all: str | None = None  # "keep everything in the left half": every structure's
    delegated: str | None = None  # "your call on sizes", "whatever": the choice left to SDI
    # "front edge at x = 0.30 m": (the face, the words) a coordinate places instead of a centre
    faces: list[tuple[str, str]] = field(default_factory=list)
    # "not stacked", "they mustn't touch": (kind, what was said), checked on the whole reading
    claims: list[tuple[str, str]] = field(default_factory=list)
    centres: str | None = None  # "100 mm apart, centre to centre": the gaps said are pitches
    # "three towers, then remove the middle one": the structures a change took out of the
    # reading, and how many of them stood inside the line (the others keep their places)
    taken: int = 0
    taken_inner: int = 0
