"""What a command says about the conversation rather than about what to build: a sentence that
recounts what happened before ("Last time the enclosure was too small. Could you build it 6 by
6?", "Left off before the bridge. Please build a bridge …"), and a structure taken back by its
name ("Castle. Wait, no castle.", "disregard my earlier message asking for a pyramid"). Both are
read out of the words before anything else counts structures, each with a note."""

from __future__ import annotations

import re

from sdi.language import corrections
from sdi.language.nouns import families_said, shape_alternation
from sdi.spec.numbers import COUNT_WORDS

_SENTENCE = re.compile(r"[^.!?]+(?:[.!?]+\s*|$)")
_TOLD_SAID = (
    r"you\s+(?:put|built|made|placed|stacked|gave|forgot)|i\s+(?:asked\s+for|wanted|ordered)|"
    r"(?:and|but)\s+got"
)
_PAST = re.compile(
    r"\b(?:last\s+time|yesterday|earlier|previously|before|left\s+off|was|were|had|fell|went|"
    r"collapsed|broke|came\s+out|ended\s+up|did\s+not|didn't|you\s+(?:set|did)|got|" + _TOLD_SAID
    + r")\b",
    re.IGNORECASE,
)
_TOLD = re.compile(r"\b(?:" + _TOLD_SAID + r")\b", re.IGNORECASE)
"""A sentence that tells what was asked or done before: its numbers are the old run's (not
"Yesterday's tower was 10 high. Build it three cubes shorter.", which a later one builds on)."""
_ASKS = re.compile(
    r"\?|\b(?:please|pls|plz|could|can|would|will|shall|build|make|put|place|stack|lay|set|"
    r"add|need|want|like|let's|lets|do|give|create|construct|arrange|erect|form|rebuild|redo|"
    r"remake|try|go|i'd|we'd)\b",
    re.IGNORECASE,
)
_NUMBER = re.compile(r"\d|\b(?:" + "|".join(sorted(COUNT_WORDS)) + r")\b", re.I)
_BUILD_IT = re.compile(
    r"\b((?:build|make|do|redo|rebuild|remake|put\s+up|set\s+up|try)\s+)(it)\b", re.IGNORECASE
)
_SHAPES = shape_alternation(min_len=3)
_FAMILY = re.compile(r"\b(" + _SHAPES + r")\b", re.IGNORECASE)


def recounted(text: str, notes: list[str]) -> str:
    """`text` without the sentences that only recount what happened before, when a later
    sentence asks for the structure they name: "it" there is that structure."""
    sentences = _SENTENCE.findall(text)
    if len(sentences) < 2:
        return text
    kept: list[str] = []
    for k, said in enumerate(sentences):
        named = families_said(said)
        asks = _ASKS.search(_TOLD.sub("", re.sub(r"\byou\s+\w+", "", said, flags=re.I)))
        numbered = _NUMBER.search(said) and not _TOLD.search(said)  # "… asked for 4, got 3"
        if not named or not _PAST.search(said) or asks or numbered:
            kept.append(said)
            continue
        later = next((j for j in range(k + 1, len(sentences)) if _ASKS.search(sentences[j])
                      or (families_said(sentences[j]) and _NUMBER.search(sentences[j]))),
                     None)  # fmt: skip
        if later is None:
            kept.append(said)
            continue
        asked = sentences[later]
        noun = _FAMILY.search(said)
        if not set(families_said(asked)) & set(named):
            if families_said(asked) or noun is None or not _BUILD_IT.search(asked):
                kept.append(said)  # the later request is for something else
                continue
            sentences[later] = _BUILD_IT.sub(rf"\g<1>the {noun.group(1)}", asked, count=1)
        notes.append(f"read '{said.strip()}' as what happened before, not as something to build")
    return "".join(kept) if len(kept) < len(sentences) else text


_TAKE_BACK = re.compile(
    r"(?:(?:\b(?:wait|actually|sorry|oh|hmm|no)\s*[,.!]?\s*)*)"
    r"(?:(?<![a-z]\s)(?<![a-z])\bno\s+(?=(?:" + _SHAPES + r")\b)|"
    r"\b(?:forget(?:\s+about)?|scrap|cancel|ditch|disregard|ignore|skip|instead\s+of|rather\s+than|"
    r"in\s+place\s+of)\s+)"
    r"(?P<words>(?:(?!and\b|then\b|but\b)[a-z']+\s+){0,6}?)"
    r"(?P<families>(?:" + _SHAPES + r")(?:\s*(?:,|or|nor|and)\s+(?:an?\s+|any\s+)?(?:"
    + _SHAPES + r"))*)\b(?!\s*\d|['’]s\b)"
    r"(?:\s+(?:idea|request|message|one|thing|part|bit|for\s+now))?"
    # "no lintel or roof on them": what is not wanted on them (not a relation of its own)
    r"(?:\s+(?:(?:on|across|over|above)\s+(?:top\s+of\s+)?(?:them|it|both)\b|on\s+top\b))?",
    re.IGNORECASE,
)


_INSTEAD = re.compile(r"\b(?:instead\s+of|rather\s+than|in\s+place\s+of)\b", re.IGNORECASE)


def _corrected_since(before: str, families: list[str]) -> bool:
    """Whether a correction ("actually", "no wait") comes after the last of `families` named."""
    last = max(before.lower().rfind(w) for w in families)
    return corrections.MARKER.search(before, last) is not None


def taken_back(text: str, notes: list[str]) -> str:
    """`text` with a structure taken back by name ("no castle", "forget the pyramid") read as
    taking back the one named before it, or, when none was, as not to be built."""
    for m in reversed(list(_TAKE_BACK.finditer(text))):
        named = families_said(m.group("families"))
        words = m.group("words")
        if not named or _NUMBER.search(words) or families_said(words):
            continue
        before = text[: m.start()]
        said_before = set(families_said(before))
        earlier = [w for w in re.findall(r"[a-z]+", m.group("families").lower())
                   if said_before & set(families_said(w))]  # fmt: skip
        if earlier and _INSTEAD.search(m.group(0)) and _corrected_since(before, earlier):
            # "a tower of 3. Actually, a wall of 4 instead of the tower": the correction says it
            text = before.rstrip(" ,;:—–-") + " " + text[m.end() :].lstrip(" ,;:—–-")
            continue
        if earlier:
            removed = "".join(f". then remove the {w}" for w in earlier)
            after = text[m.end() :].lstrip(" .,;:—–-")
            text = before.rstrip(" .,;:—–-") + removed + ". " + after
            continue
        notes.append(f"left out what is not wanted: '{m.group(0).strip()}'")
        text = before.rstrip(" ,;:—–-") + " " + text[m.end() :].lstrip(" ,;:—–-")
    return text
