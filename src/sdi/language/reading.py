"""What the Specifier read: the semantic tree of a command and its account of every word."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from sdi.spec.structure_spec import Spec

SpecSource = Literal["grammar", "model"]


class Reading(BaseModel):
    """A command read into structures and relations (`spec`), with what was assumed,
    corrected and ignored.

    `complete` is the honesty bit: False when a material word of the command — a number, a
    negation, a shape, size, region or relation word, or any other content word with a
    possible bearing on the layout — was not used. A plan built from an incomplete reading
    is ``partial``, never ``success``.
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    command: str
    text: str = Field(description="the command after normalisation and typo correction")
    spec: Spec
    phrases: tuple[str, ...] = Field((), description="the noun phrases that name structures")
    notes: tuple[str, ...] = Field((), description="assumptions, corrections, ignored words")
    ignored: tuple[str, ...] = Field((), description="words of the command left unused")
    material: tuple[str, ...] = Field(
        (), description="what was left unused that changes what would be built"
    )
    source: SpecSource = "grammar"

    @property
    def complete(self) -> bool:
        return not self.material

    def to_json_dict(self) -> dict[str, object]:
        names = [f"{s.shape}#{k + 1}" for k, s in enumerate(self.spec.structures)]
        return {
            "source": self.source,
            "structures": [
                {"id": names[k], **s.model_dump(mode="json", exclude_none=True)}
                for k, s in enumerate(self.spec.structures)
            ],
            "relations": [
                {
                    "kind": r.kind,
                    "subject": names[r.subject],
                    "object": names[r.object],
                    **({"side": r.side} if r.side else {}),
                }
                for r in self.spec.relations
            ],
            "complete": self.complete,
            "text": self.text,
        }
