"""The language front end: a plain-language command → a `Reading` (structures, relations,
and an account of every word). See `sdi.language.reader` for the stages
and the module of each."""

from sdi.language.families import FAMILIES, check_family
from sdi.language.reader import read
from sdi.language.reading import Reading

__all__ = ["FAMILIES", "Reading", "check_family", "read"]
