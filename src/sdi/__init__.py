"""SDI — Specifier · Designer · Inspector.

Plain-language commands become verified, sequenced robot assembly plans. The package reads as
the pipeline: `spec` (command → structure spec) → `design` (spec → layout) → `inspector`
(verify + sequence) → `skills` (the tool-callable registry) → `pipeline` (end to end) → `cli`.
"""

from sdi.errors import (
    InfeasibleError,
    InputError,
    LimitError,
    SDIError,
    SequencingError,
    SpecError,
)
from sdi.model import CellConfig, Layout, Part, load_layout, parse_layout

__all__ = [
    "CellConfig",
    "InfeasibleError",
    "InputError",
    "Layout",
    "LimitError",
    "Part",
    "SDIError",
    "SequencingError",
    "SpecError",
    "load_layout",
    "parse_layout",
]
__version__ = "0.1.0"
