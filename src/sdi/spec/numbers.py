"""Numbers written as words ("twenty-five", "a dozen", "half a metre") to values."""

from __future__ import annotations

UNITS = {
    "zero": 0, "no": 0, "one": 1, "single": 1, "two": 2, "three": 3, "four": 4, "five": 5,
    "six": 6, "seven": 7, "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12,
    "thirteen": 13, "fourteen": 14, "fifteen": 15, "sixteen": 16, "seventeen": 17,
    "eighteen": 18, "nineteen": 19,
}  # fmt: skip
TENS = {
    "twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70,
    "eighty": 80, "ninety": 90,
}  # fmt: skip
SCALES = {"hundred": 100, "thousand": 1000}
# Quantity words and the count they stand for.
QUANTITY_WORDS = {
    "dozen": 12, "couple": 2, "pair": 2, "twin": 2, "double": 2, "triple": 3, "trio": 3,
    "quad": 4, "quadruple": 4, "handful": 5, "few": 3, "several": 4, "some": 3, "many": 8,
    "lots": 8, "bunch": 6, "multiple": 3, "both": 2,
}  # fmt: skip
COUNT_WORDS = (frozenset(UNITS) | frozenset(TENS)) - {"no", "zero", "single"}
"""Words that say how many ("one" included; "no" and "zero" say none, "single" is a size word)."""
NUMBER_WORDS = COUNT_WORDS - {"one"}
"""Words that say a number and nothing else ("one" is also a pronoun, "no" a negation)."""
FACTORS = {"twice": 2.0, "double": 2.0, "thrice": 3.0, "half": 0.5, "just": 1.0, "exactly": 1.0,
           "equally": 1.0}  # fmt: skip
"""What "… as tall" multiplies by ("twice as tall", "just as long")."""
ORDINAL_STEPS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6,
                 "seventh": 7, "eighth": 8}  # fmt: skip
MULTIPLIERS = {"once": 1, "twice": 2, "thrice": 3}


def words_to_numbers(tokens: list[str]) -> list[str]:
    """Replace runs of number words by digits: ``["twenty", "five"] → ["25"]``.

    "a dozen" → 12, "half a dozen" → 6, "one hundred and twenty" → 120. Other tokens pass.
    """
    out: list[str] = []
    i = 0
    n = len(tokens)
    while i < n:
        t = tokens[i]
        if t == "half" and i + 2 < n and tokens[i + 1] in ("a", "an") and tokens[i + 2] == "dozen":
            out.append("6")
            i += 3
            continue
        if t == "half" and i + 1 < n and tokens[i + 1] == "dozen":  # "a half dozen"
            if out and out[-1] in ("a", "an"):
                out.pop()
            out.append("6")
            i += 2
            continue
        if t in UNITS or t in TENS or (t in SCALES and out and out[-1].isdigit()):
            total, current, j, used = 0, 0, i, False
            while j < n:
                w = tokens[j]
                if w in UNITS and not (w == "no" and used):
                    if w == "no" and j + 1 < n and tokens[j + 1] not in UNITS:
                        break
                    if current % 10 or (used and current < 20 and current):
                        break  # "two eight-cube stacks": two numbers, not 2 + 8
                    current += UNITS[w]
                elif w in TENS:
                    current += TENS[w]
                elif w in SCALES and used:
                    current = max(current, 1) * SCALES[w]
                    if SCALES[w] >= 1000:
                        total, current = total + current, 0
                elif (
                    w == "and"
                    and used
                    and j + 1 < n
                    and (tokens[j + 1] in UNITS or tokens[j + 1] in TENS)
                ) or (w == "-" and used and j + 1 < n and tokens[j + 1] in UNITS):
                    pass
                else:
                    break
                used = True
                j += 1
            if used:
                if t == "no" and j == i + 1:
                    out.append(t)
                    i += 1
                    continue
                out.append(str(total + current))
                i = j
                continue
        out.append(t)
        i += 1
    return out
