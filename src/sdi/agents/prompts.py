"""Prompts for the neural agents: minimal system prompt, few-shot examples, and φ(E).

The constraint texts are what the adaptive loop injects for violated constraints only
(paper §III-C: s_retry = s_minimal + [error] + φ(E)); LLM-FullPrompt puts all of them in.
"""

from __future__ import annotations

import json

from sdi.inspector.violation import Constraint, Violation
from sdi.model.cell import CellConfig

CONSTRAINT_TEXT: dict[Constraint, str] = {
    Constraint.WORKSPACE: "Every part's box must lie inside the workspace cuboid.",
    Constraint.COLLISION: "Boxes of different parts must not overlap (touching faces is fine).",
    Constraint.CONTACT: "A part above the table must touch another part.",
    Constraint.SUPPORT: "A part above the table must rest on the top face of a part below it.",
    Constraint.STABILITY: "The centre of mass of every sub-structure must lie over its support.",
    Constraint.GRAVITY: "Lower parts in contact are placed before the parts above them.",
    Constraint.SEQUENCE: "Supporting parts come before the parts they support.",
    Constraint.GRIPPING: "When placed, a part needs a free side pair (fingers) or a free top.",
}


def _vector(n: int) -> dict[str, object]:
    return {"type": "array", "items": {"type": "number"}, "minItems": n, "maxItems": n}


LAYOUT_OUTPUT_SCHEMA: dict[str, object] = {
    "type": "object",
    "properties": {
        "objects": {
            "type": "array",
            "minItems": 1,
            "items": {
                "type": "object",
                "properties": {
                    "id": {"type": "string"},
                    "position": _vector(3),
                    "size": _vector(3),
                },
                "required": ["id", "position", "size"],
                "additionalProperties": False,
            },
        }
    },
    "required": ["objects"],
    "additionalProperties": False,
}
"""What the Designer must answer: at least one part, each with id, position and size. Stricter
than the layout file format (whose `objects` may be empty and whose size has a default), so a
grammar-constrained server cannot satisfy it with `{}`; plain types only, which every
structured-output implementation (OpenAI, llama.cpp's grammar, vLLM) understands. The Inspector
still parses the answer as a full `Layout`."""


def system_prompt(cell: CellConfig) -> str:
    ws = cell.workspace
    s = cell.cube
    return (
        "You design structures of box parts for a robot cell. Units are metres. A part is "
        '{"id": str, "position": [x, y, z] (centre of the box), "size": [sx, sy, sz]}. '
        f"The table top is z = 0; the default part is a cube of {s[0]} m, so a cube on the "
        f"table has z = {s[2] / 2}. The workspace is x {ws.x_min}–{ws.x_max}, y "
        f"{ws.y_min}–{ws.y_max}, z {ws.z_min}–{ws.z_max}. Stack cubes by adding {s[2]} m to z. "
        'Answer with JSON only: {"objects": [...]}.'
    )


FEW_SHOT = [
    (
        "a 2-cube tower at x = 0.4, y = 0.3",
        {"objects": [
            {"id": "c1", "position": [0.4, 0.3, 0.025], "size": [0.05, 0.05, 0.05]},
            {"id": "c2", "position": [0.4, 0.3, 0.075], "size": [0.05, 0.05, 0.05]},
        ]},
    ),
]  # fmt: skip


def few_shot_messages() -> list[dict[str, str]]:
    out: list[dict[str, str]] = []
    for command, layout in FEW_SHOT:
        out.append({"role": "user", "content": command})
        out.append({"role": "assistant", "content": json.dumps(layout)})
    return out


def phi(violations: list[Violation] | tuple[Violation, ...]) -> str:
    """φ(E): the texts of only the violated constraints, then each violation with its hint."""
    codes = sorted({v.constraint for v in violations}, key=lambda c: c.value)
    rules = "\n".join(f"- {c.value}: {CONSTRAINT_TEXT[c]}" for c in codes)
    found = "\n".join(f"- {v.message}. Fix: {v.hint}" for v in list(violations)[:12])
    return f"Constraints you broke:\n{rules}\nViolations:\n{found}"


def all_constraints() -> str:
    return "\n".join(f"- {c.value}: {t}" for c, t in CONSTRAINT_TEXT.items())


SPEC_PROMPT = (
    "Turn the operator's command into a structure specification. Answer with JSON only, matching "
    "the schema. Use shape names from the schema, counts in parts (a cube is 0.05 m), positions "
    "in metres (at_x, at_y) only when the command states them, and a region (left, right, front, "
    "back, centre, or combinations like 'back left') when it names one, and 'edge' (the sides "
    "of the workspace it stands against) when it says 'as far back as it goes' or 'along the "
    "left edge'. One entry in "
    "'structures' per structure. When the command relates structures, add 'relations' with "
    "indices into 'structures': on_top_of (subject stands on object), around (subject, a ring, "
    "encloses object), next_to (subject beside object, with side left/right/front/back). Towers "
    "joined by a beam are one bridge (height = tower height, spans = towers - 1)."
)
