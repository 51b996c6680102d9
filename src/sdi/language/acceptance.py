"""A tester's acceptance criteria: the build written as GIVEN / WHEN / THEN.

"GIVEN an empty table WHEN the robot builds THEN exactly 2 towers of height 3 exist": the
GIVEN says what the table holds before, the WHEN what is done, the THEN what stands when it is
done. SDI builds on an empty table, so what the THEN names is what to build: "GIVEN a tower of
5 WHEN the top 2 cubes are removed THEN a tower of 3 remains" is a tower of 3 (both were built).
An empty table is where SDI starts, never a structure (a table of its default size was built
beside the towers); "exists", "remains" only say a structure is there."""

from __future__ import annotations

import re

from sdi.language.nouns import families_said

_TABLE = r"(?:table|workspace|work\s*space|work\s+area|cell|bench|surface)"
# "an empty table", "GIVEN emtpy table", "table empty", "the workspace is clear"
_EMPTY = re.compile(
    r"\b(?:(?:an?|the)\s+)?(?:empty|emtpy|clear|bare|clean)\s+" + _TABLE + r"\b"
    r"|(?:^|(?<=[.:;,]\s)|(?<=given\s)|(?<=GIVEN\s))(?:the\s+)?" + _TABLE
    + r"\s+(?:is\s+)?(?:empty|emtpy|clear|bare)\b"
    r"(?!\s+(?:of|for|from|around|between|in|at|on)\b)",
    re.IGNORECASE,
)
# the keywords as a tester writes them: in capitals, or "Given …, when …, then …" from the start
_SECTION = re.compile(r"\b(GIVEN|WHEN|THEN)\b")
_SECTION_PROSE = re.compile(r"(?:^|(?<=[,;.]\s))(given|when|then)\b", re.IGNORECASE)
_THERE = re.compile(
    r"\s+(?:exists?|remains?|(?:is|are)\s+(?:present|left|standing))(?:\s+on\s+the\s+table)?"
    r"(?=\s*(?:[.,;!]|\band\b|$))",
    re.IGNORECASE,
)
_SPANNING = {"bridge", "arch", "canopy"}
_SPANNED = re.compile(r"\b(?:beams?|top|roof|slab|plank|deck)\b", re.IGNORECASE)
_PARTS = re.compile(r"\b(?:pillars?|posts?|legs?|beams?|cubes?)\b", re.IGNORECASE)


def take(text: str, notes: list[str]) -> str:
    """`text` with a GIVEN / WHEN / THEN frame read (unchanged when it has none)."""
    said: list[str] = []

    def empty(m: re.Match[str]) -> str:
        said.append(m.group(0).strip())
        return " "

    text = _EMPTY.sub(empty, text)
    if said:
        notes.append(f"read '{said[0]}' as the table SDI starts from, not a structure to build")
    # a frame: GIVEN said, or WHEN and THEN both ("BUILD A ROW OF 6 THEN A TOWER" in capitals
    # is a sequence, not a frame), or "Given …" opening the command
    capitals = {m.group(1) for m in _SECTION.finditer(text)}
    framed = "GIVEN" in capitals or {"WHEN", "THEN"} <= capitals
    if not framed and not re.match(r"\s*given\b", text, re.IGNORECASE):
        return text
    pattern = _SECTION if framed else _SECTION_PROSE
    cuts = list(pattern.finditer(text))
    sections = [
        (m.group(1).upper(), text[m.end() : cuts[k + 1].start() if k + 1 < len(cuts) else None])
        for k, m in enumerate(cuts)
    ]
    then = " ".join(s for key, s in sections if key == "THEN")
    before = " ".join(
        f"{key} {s.strip(' ,;.')}" for key, s in sections if key != "THEN" and s.strip(" ,;.")
    )
    # "WHEN I request a bridge THEN 2 pillars of 2 and a beam spans them": the bridge's parts
    its_parts = set(families_said(before)) & _SPANNING and _SPANNED.search(then)
    # a THEN that names new structures ("THEN 2 towers of 3 exist"), not one that says how those
    # named before stand ("Then the tower does not touch the ring")
    named_new = re.search(r"\b(?:an?|one|\d+|two|three|four|five|six|exactly|there\s+(?:is|are))\b",
                          then, re.IGNORECASE)  # fmt: skip
    if families_said(then) and named_new and not its_parts:
        if before and (families_said(before) or _PARTS.search(before)):
            notes.append(f"read '{before}' as how the build comes about: the THEN says what "
                         "stands at the end, and that is built")  # fmt: skip
        text = text[: cuts[0].start()] + " " + then
    else:
        text = pattern.sub(". ", text)
    notes.append("read GIVEN / WHEN / THEN as acceptance criteria")
    return _THERE.sub("", text)
