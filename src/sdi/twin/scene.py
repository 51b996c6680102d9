"""The twin's fixed scene: table, workspace W, supply areas and the robots read from their URDFs.

The robots are sent to the browser as their URDF kinematic chain (joint origins and axes) and
visual primitives, parsed with yourdfpy from the very URDF the simulator loads
(`sdi.robot.urdf_xml`), plus each arm's base pose and home joints. The page computes forward
kinematics itself, so a robot pose on the wire is six numbers, never a mesh or a frame list.
"""

from __future__ import annotations

import io
from typing import Any

import numpy as np
import yourdfpy

from sdi.commission import EPSILON
from sdi.model.cell import CellConfig
from sdi.motion.scene import TABLE_CENTRE, TABLE_HALF
from sdi.robot import RobotModel, robots_for, urdf_xml

PLACED_TOLERANCE_M = 0.005
"""A placed part is shown as placed (green) when it stands this close to its target, m — the
physics check's "stands" criterion."""


def _m(T: np.ndarray) -> list[float]:
    """A 4×4 transform as 16 numbers, row-major."""
    return [round(float(v), 6) for v in np.asarray(T, dtype=float).reshape(-1)]


def _visual(v: Any, materials: dict[str, Any]) -> dict[str, Any] | None:
    g = v.geometry
    origin = v.origin if v.origin is not None else np.eye(4)
    colour = None
    material = v.material
    if material is not None and material.color is None and material.name in materials:
        material = materials[material.name]
    if material is not None and material.color is not None:
        colour = [round(float(c), 3) for c in material.color.rgba]
    if g.box is not None:
        shape = {"kind": "box", "size": [float(s) for s in g.box.size]}
    elif g.cylinder is not None:
        shape = {"kind": "cylinder", "radius": g.cylinder.radius, "length": g.cylinder.length}
    elif g.sphere is not None:
        shape = {"kind": "sphere", "radius": g.sphere.radius}
    else:  # a mesh: the project's URDFs have none
        return None
    return {**shape, "origin": _m(origin), "colour": colour}


def robot_description(model: RobotModel) -> dict[str, Any]:
    """One arm for the page: its URDF chain (root first), visuals per link, base pose."""
    urdf = yourdfpy.URDF.load(
        io.StringIO(urdf_xml(model)), load_meshes=False, build_scene_graph=False
    )
    robot = urdf.robot
    by_parent = {j.parent: j for j in robot.joints}
    children = {j.child for j in robot.joints}
    base = next(lk.name for lk in robot.links if lk.name not in children)
    materials = {m.name: m for m in robot.materials}
    chain: list[dict[str, Any]] = []
    link = base
    while link in by_parent:
        j = by_parent[link]
        origin = j.origin if j.origin is not None else np.eye(4)
        axis = [float(a) for a in (j.axis if j.axis is not None else (0.0, 0.0, 1.0))]
        chain.append({"name": j.name, "type": j.type, "child": j.child,
                      "origin": _m(origin), "axis": axis})  # fmt: skip
        link = j.child
    visuals = {
        lk.name: [d for d in (_visual(v, materials) for v in lk.visuals) if d is not None]
        for lk in robot.links
    }
    return {
        "name": model.name,
        "base_link": base,
        "T_world_base": _m(model.T_world_base),
        "chain": chain,
        "visuals": visuals,
        "joint_names": list(model.joint_names),
    }


def scene(cell: CellConfig) -> dict[str, Any]:
    """Everything that does not change during a run, for the page to draw once."""
    from sdi.tasks.generator import TaskGenerator

    ws = cell.workspace
    robots = robots_for(cell)
    home = TaskGenerator(cell).home
    return {
        "table": {"centre": list(TABLE_CENTRE), "half": list(TABLE_HALF)},
        "workspace": {"lower": list(ws.lower), "upper": list(ws.upper)},
        "supply_areas": [
            {"name": a.name, "robot": a.robot, "x": list(a.x_range), "y": list(a.y_range)}
            for a in cell.supply_areas
        ],
        "robots": [
            {**robot_description(m), "home": [round(float(q), 6) for q in home[n]]}
            for n, m in robots.items()
        ],
        "cube": list(cell.cube),
        "part_types": {k: list(v) for k, v in cell.part_types.items()},
        "grid_m": cell.cube[0] / 2,
        "epsilon_rad": EPSILON,
        "placed_tolerance_m": PLACED_TOLERANCE_M,
    }
