"""Geometry and configuration values: parts, layouts, the cell."""

from sdi.model.cell import CellConfig, ParallelGripper, SupplyArea, VacuumGripper, Workspace
from sdi.model.layout import Layout, load_layout, parse_layout
from sdi.model.part import Part, quat_from_yaw

__all__ = [
    "CellConfig",
    "Layout",
    "ParallelGripper",
    "Part",
    "SupplyArea",
    "VacuumGripper",
    "Workspace",
    "load_layout",
    "parse_layout",
    "quat_from_yaw",
]
