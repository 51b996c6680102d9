"""Whose left: places said from where the speaker stands, turned into the robot's frame.

SDI's left, right, front and back are the robot's (it stands at the front of the table, facing
the back). An operator often stands across the table, facing the robot; said so ("I'm opposite
the robot", "from the visitor side", "standing across the table from it"), their left is the
robot's right, "nearest me" / "my side" the back and "the far side from me" the front. A
viewpoint said once holds for the whole message; "the robot's left" stays the robot's. Without
a viewpoint, "my left" is read as the robot's left, and a note says so."""

from __future__ import annotations

import re

from sdi.spec import lexicon as lx

_ROBOT = r"(?:the\s+)?(?:robot|arm|machine)"
_TABLE = r"(?:the\s+)?(?:table|cell|bench|workspace|work\s+area)"

# the speaker says they stand facing the robot, across the table from it
_ACROSS = re.compile(
    r"(?:(?:as\s+)?(?:seen|looking|viewed|looked\s+at|as\s+I\s+(?:see|look\s+at)\s+(?:it|them))"
    r"\s+)?(?:from\s+where\s+I(?:'m|\s+am)?\s+(?:stand(?:ing)?|sit(?:ting)?|am)\s*,?\s*)?"
    r"(?:(?:I(?:'m|\s+am)|im|we(?:'re|\s+are))\s+)?"
    r"(?:(?:I\s+(?:stand|sit|work)|standing|sitting|working)\s+)?"
    r"(?:(?:across|opp?os+ite)\s+(?:from\s+)?" + _ROBOT + r"(?:\s+(?:across|at)\s+" + _TABLE + r")?"
    # "I'm across the table.", "I'm standing across from it": the robot is what they face
    r"|(?:(?<=\bI'm\s)|(?<=\bim\s)|(?<=\bam\s)|(?<=ing\s))across\s+(?:"
    + _TABLE
    + r"|from\s+(?:it|him|her))(?=\s*[,.;:!-]|\s*$)"
    r"|(?:across|on\s+the\s+(?:other|far)\s+side\s+of)\s+" + _TABLE + r"\s+from\s+"
    r"(?:" + _ROBOT + r"|it)"
    r"|facing\s+" + _ROBOT + r"(?:\s+across\s+" + _TABLE + r")?"
    r"|(?:from|(?<=I'm\s)(?:on|at)|(?<=I\sam\s)(?:on|at)|(?<=standing\s)(?:on|at))"
    r"\s+the\s+(?:visitors?'?s?|other|far|opposite)\s+side"
    r"(?:\s+of\s+" + _TABLE + r")?(?=\s*[,.;:!-]|\s+(?:and|so|facing)\b|\s*$)"
    r"|from\s+the\s+side\s+(?:of\s+"
    + _TABLE
    + r"\s+)?opposite\s+"
    + _ROBOT
    + r"|with\s+"
    + _ROBOT
    + r"\s+facing\s+me)",
    re.IGNORECASE,
)

_ITS_PLACE = re.compile(r"\s*on\s+the\s+(?:far|other)\b", re.IGNORECASE)

# "the robot's left": the robot's own frame, said outright
_ROBOTS = re.compile(
    r"\b(?:the\s+)?(?:robot|arm|machine)'?s\s+(?:own\s+)?(left|right|front|back)\b", re.I
)
_ROBOTS_SIDE = re.compile(r"\b(?:the\s+)?(?:robot|arm|machine)'?s\s+(?:side|end)\b", re.I)

_SIDES = re.compile(r"\b(left|right)(?=\b|-)", re.IGNORECASE)
_MY_SIDE = re.compile(r"\b(?:(?:to|on|at|towards?)\s+)?my\s+(left|right)\b", re.IGNORECASE)
_MY = re.compile(r"\bmy\s+(?=(?:left|right)\b)", re.IGNORECASE)

# places relative to the speaker, in the robot's frame when they stand across the table
_NEAR_ME = re.compile(
    r"\b(?:(?:the\s+(?:side|end)\s+)?(?:near(?:est)?|clos(?:e|est))\s+(?:to\s+)?me"
    r"|(?:on|at)\s+my\s+(?:side|end)(?:\s+of\s+" + _TABLE + r")?|my\s+(?:side|end)"
    r"(?:\s+of\s+" + _TABLE + r")?)\b",
    re.IGNORECASE,
)
_FAR_FROM_ME = re.compile(
    r"\b(?:the\s+)?(?:far(?:thest|th?est)?|furthest)\s+(?:side|end)?\s*(?:from|away\s+from)\s+me"
    r"|\b(?:the\s+)?far\s+(?:side|end)(?:\s+of\s+" + _TABLE + r")?(?!\s+from)\b"
    r"|\b(?:the\s+)?(?:side|end)\s+(?:farthest|furthest)\s+from\s+me\b",
    re.IGNORECASE,
)
_TOWARDS_ME = re.compile(r"\btowards?\s+me\b", re.IGNORECASE)
_AWAY_FROM_ME = re.compile(r"\baway\s+from\s+me\b", re.IGNORECASE)
# "in front of it as I see it": between the speaker and it
_AS_I_SEE = re.compile(
    r"\b(in\s+front\s+of|behind)\s+((?:it|them|the\s+\w+(?:\s+\w+)?))\s*,?\s*"
    r"(?:as\s+I\s+(?:see|look\s+at)\s+(?:it|them)|from\s+(?:me|where\s+I\s+(?:stand|am))"
    r"|[—–-]*\s*between\s+me\s+and\s+(?:it|them))\b",
    re.IGNORECASE,
)
# "beyond it from me", "on the far side of the big tower (6) from me": in front of it
_BEYOND = re.compile(
    r"\b(?:beyond|on\s+the\s+(?:far|other)\s+side\s+of)\s+(it|them|the\s+\w+(?:\s+\w+)?)"
    r"(\s*\(\s*\d+\s*\))?\s+from\s+me\b",
    re.IGNORECASE,
)
_BETWEEN_ME = re.compile(r"\bbetween\s+me\s+and\s+(it|them|the\s+\w+)\b", re.IGNORECASE)
# "the far corner on my right", "my edge": the front corner, the back edge
_FAR_CORNER = re.compile(r"\b(?:the\s+)?(?:far(?:thest|th?est)?|furthest)\s+(corner|edge)\b", re.I)
_NEAR_CORNER = re.compile(r"\b(?:the\s+)?(?:near(?:est)?|closest)\s+(corner|edge)\b", re.I)
_MY_EDGE = re.compile(r"\bmy\s+(?:own\s+)?edge(?:\s+of\s+" + _TABLE + r")?", re.IGNORECASE)


def _flip(side: str) -> str:
    other = lx.OPPOSITE_SIDE[side.lower()]
    return other.capitalize() if side[:1].isupper() else other


def take(text: str, notes: list[str]) -> str:
    """`text` with its places in the robot's frame; a note for each viewpoint used."""
    text = text.replace("’", "'")  # "I’m opposite the robot"
    # "a staircase on the far side of the table from the robot" is where it stands, not they
    said = next(
        (m for m in _ACROSS.finditer(text) if not _ITS_PLACE.match(m.group(0))), None
    )
    if said is None:
        return _own_frame(text, notes)
    text = text[: said.start()] + " " + text[said.end() :]
    # the robot's own words keep the robot's frame: shield them from the turn below
    shielded: list[str] = []

    def shield(m: re.Match[str]) -> str:
        shielded.append(m.group(1).lower())
        return f" the \x00{len(shielded) - 1}\x00 "

    text = _ROBOTS.sub(shield, text)
    text = _ROBOTS_SIDE.sub(" the front ", text)
    turns: list[str] = []

    def turn(pattern: re.Pattern[str], text: str, repl: str, said: str) -> str:
        out, n = pattern.subn(repl, text)
        if n:
            turns.append(said)
        return out

    seen = _AS_I_SEE.sub(
        lambda m: (
            ("behind " if m.group(1).lower().startswith("in") else "in front of ") + m.group(2)
        ),
        text,
    )
    seen = _BEYOND.sub(lambda m: f"in front of {m.group(1)}{m.group(2) or ''}", seen)
    seen = _BETWEEN_ME.sub(lambda m: f"behind {m.group(1)}", seen)
    if seen != text:
        turns.append("in front of a structure as they see it is behind it")
    seen = turn(_MY_EDGE, seen, " the back edge ", "their edge is the back")
    seen = turn(_FAR_CORNER, seen, r" the front \1 ", "the far corner from them is at the front")
    seen = turn(_NEAR_CORNER, seen, r" the back \1 ", "the corner near them is at the back")
    text = turn(_NEAR_ME, seen, " at the back ", "the side near them is the back")
    text = turn(_FAR_FROM_ME, text, " the front ", "the far side from them the front")
    text = turn(_TOWARDS_ME, text, " towards the back ", "towards them is towards the back")
    text = turn(_AWAY_FROM_ME, text, " towards the front ", "away from them towards the front")
    text = _MY.sub("the ", text)
    if _SIDES.search(text):
        turns.append("their left is the robot's right")
    text = _SIDES.sub(lambda m: _flip(m.group(1)), text)
    text = re.sub("\x00(\\d+)\x00", lambda m: shielded[int(m.group(1))], text)
    notes.append(
        f"read the places from where the speaker stands ('{said.group(0).strip()}'), across "
        "the table from the robot, facing it" + (": " + ", ".join(turns) if turns else "")
    )
    return text


def _own_frame(text: str, notes: list[str]) -> str:
    """No viewpoint said: "the robot's left" is SDI's own left; "my left" is read as the
    robot's, said in a note."""
    text = _ROBOTS.sub(lambda m: f" the {m.group(1).lower()} ", text)
    text = _ROBOTS_SIDE.sub(" the front ", text)
    mine = _MY_SIDE.search(text)
    if mine is not None:
        notes.append(
            f"read '{mine.group(0).strip()}' as the robot's {mine.group(1).lower()} (where the "
            "speaker stands was not said; say 'I'm opposite the robot' if it faces you)"
        )
        text = _MY.sub("the ", text)
    return text
