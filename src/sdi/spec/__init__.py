"""The structured specification l̂ (`Spec`) and the phrase grammar that fills its slots.

`parse_command` reads a whole command through the language front end (`sdi.language`).
"""

from __future__ import annotations

from sdi.model.cell import CellConfig
from sdi.spec.structure_spec import SHAPES, Relation, Spec, StructureSpec, structure


def parse_command(command: str, cell: CellConfig | None = None) -> Spec:
    """The offline Specifier: a command → `Spec`, or `SpecError` saying what it understood."""
    from sdi.language import read

    return read(command, cell).spec


__all__ = ["SHAPES", "Relation", "Spec", "StructureSpec", "parse_command", "structure"]
