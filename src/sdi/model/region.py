"""Blocked regions: parts of the cell a structure must stay out of (failure injection, recovery).

A region is an axis-aligned box with optional bounds (a missing bound is unbounded), or a
half-space ``normal · p > offset`` (e.g. the diagonal obstacle x + y > 0.7). Metres.
"""

from __future__ import annotations

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, model_validator


class Region(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")

    name: str = ""
    x_min: float | None = None
    x_max: float | None = None
    y_min: float | None = None
    y_max: float | None = None
    z_min: float | None = None
    z_max: float | None = None
    normal: tuple[float, float, float] | None = Field(
        None, description="half-space: blocked where normal · p > offset"
    )
    offset: float | None = None

    @model_validator(mode="after")
    def _consistent(self) -> Region:
        if (self.normal is None) != (self.offset is None):
            raise ValueError("a half-space region needs both normal and offset")
        if self.normal is not None and not any(self.normal):
            raise ValueError("normal must not be zero")
        return self

    def blocks(self, lo: np.ndarray, hi: np.ndarray, eps: float = 1e-9) -> np.ndarray:
        """Which boxes (rows of `lo`/`hi`, shape (N, 3)) reach into the region's interior."""
        lo, hi = np.atleast_2d(lo), np.atleast_2d(hi)
        hit = np.ones(lo.shape[0], dtype=bool)
        for d, axis in enumerate("xyz"):
            low, high = getattr(self, f"{axis}_min"), getattr(self, f"{axis}_max")
            if low is not None:
                hit &= hi[:, d] > low + eps
            if high is not None:
                hit &= lo[:, d] < high - eps
        if self.normal is not None and self.offset is not None:
            n = np.asarray(self.normal)
            centre, half = (lo + hi) / 2, (hi - lo) / 2
            hit &= centre @ n + half @ np.abs(n) > self.offset + eps
        return hit

    def describe(self) -> str:
        if self.name:
            return self.name
        parts = []
        for axis in "xyz":
            low, high = getattr(self, f"{axis}_min"), getattr(self, f"{axis}_max")
            if low is not None and high is not None:
                parts.append(f"{low:g} < {axis} < {high:g}")
            elif low is not None:
                parts.append(f"{axis} > {low:g}")
            elif high is not None:
                parts.append(f"{axis} < {high:g}")
        if self.normal is not None:
            parts.append(f"{self.normal}·p > {self.offset:g}")
        return " and ".join(parts) or "everywhere"
