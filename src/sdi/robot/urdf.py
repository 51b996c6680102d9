"""URDF export of a `RobotModel`: the arm, its gripper and a TCP frame, from primitives only.

The URDF's root link ``base_link`` is the robot base frame; the world placement
``T_world_base`` is not written (whoever loads the file applies it, e.g. pybullet's
``basePosition``/``baseOrientation``). Tree::

    base_link ─joint_1─ link_1 ─ … ─joint_6─ link_6 ─joint_flange─ flange (= tool0)
        ─joint_gripper─ gripper ─joint_tcp─ tcp

Collision and visual geometry are the same boxes, cylinders and spheres (robots.md "Link
collision boxes"); each link's inertial is a solid of its (estimated) mass filling its first
shape. Frame-only links carry a 1 g placeholder inertial so that simulators which default a
missing inertial to 1 kg (pybullet) do not add phantom mass.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from sdi.robot.model import LINK_NAMES, T_LINK6_FLANGE, CollisionShape, RobotModel
from sdi.robot.transforms import rpy_from_matrix

FLANGE_LINK = "flange"
GRIPPER_LINK = "gripper"
TCP_LINK = "tcp"

_AXES = {"x": "1 0 0", "y": "0 1 0", "z": "0 0 1"}
_FRAME_MASS_KG = 0.001
_FRAME_INERTIA = 1e-6
_ARM_COLOUR = ("abb_graphite_white", "0.85 0.85 0.82 1")
_TOOL_COLOUR = ("onrobot_grey", "0.25 0.25 0.27 1")


def _fmt(value: float) -> str:
    v = float(value)
    return "0" if abs(v) < 1e-15 else repr(v)


def _vec(values: object) -> str:
    return " ".join(_fmt(v) for v in np.asarray(values, dtype=float).reshape(-1))


def _origin(parent: ET.Element, T: np.ndarray) -> None:
    ET.SubElement(parent, "origin", xyz=_vec(T[:3, 3]), rpy=_vec(rpy_from_matrix(T[:3, :3])))


def _geometry(parent: ET.Element, shape: CollisionShape) -> None:
    geometry = ET.SubElement(parent, "geometry")
    d = shape.dimensions
    if shape.kind == "box":
        ET.SubElement(geometry, "box", size=_vec([2 * d[0], 2 * d[1], 2 * d[2]]))
    elif shape.kind == "cylinder":
        ET.SubElement(geometry, "cylinder", radius=_fmt(d[0]), length=_fmt(2 * d[1]))
    else:
        ET.SubElement(geometry, "sphere", radius=_fmt(d[0]))


def _inertial(link: ET.Element, mass: float, shape: CollisionShape | None) -> None:
    inertial = ET.SubElement(link, "inertial")
    if shape is None:
        ET.SubElement(inertial, "origin", xyz="0 0 0", rpy="0 0 0")
        moments = (_FRAME_INERTIA,) * 3
    else:
        _origin(inertial, shape.T_link_shape)
        moments = shape.inertia_diagonal(mass)
    ET.SubElement(inertial, "mass", value=_fmt(mass))
    ET.SubElement(
        inertial,
        "inertia",
        ixx=_fmt(moments[0]),
        ixy="0",
        ixz="0",
        iyy=_fmt(moments[1]),
        iyz="0",
        izz=_fmt(moments[2]),
    )


def _link(
    robot: ET.Element,
    name: str,
    shapes: tuple[CollisionShape, ...],
    mass: float,
    material: str,
) -> None:
    link = ET.SubElement(robot, "link", name=name)
    _inertial(link, mass, shapes[0] if shapes else None)
    for shape in shapes:
        visual = ET.SubElement(link, "visual")
        _origin(visual, shape.T_link_shape)
        _geometry(visual, shape)
        ET.SubElement(visual, "material", name=material)
    for shape in shapes:
        collision = ET.SubElement(link, "collision")
        _origin(collision, shape.T_link_shape)
        _geometry(collision, shape)


def _fixed_joint(robot: ET.Element, name: str, parent: str, child: str, T: np.ndarray) -> None:
    joint = ET.SubElement(robot, "joint", name=name, type="fixed")
    ET.SubElement(joint, "parent", link=parent)
    ET.SubElement(joint, "child", link=child)
    _origin(joint, T)


def urdf_xml(model: RobotModel) -> str:
    """The URDF document (a string) of `model`'s arm, tool and TCP, in the robot base frame.

    Revolute joints ``joint_1`` … ``joint_6`` carry the position limits (rad), velocity
    limits (rad/s) and nominal efforts (N·m) of the model; acceleration limits have no place
    in URDF and stay in `RobotModel.max_acceleration`.
    """
    robot = ET.Element("robot", name=model.name)
    for name, rgba in (_ARM_COLOUR, _TOOL_COLOUR):
        ET.SubElement(ET.SubElement(robot, "material", name=name), "color", rgba=rgba)

    for name, shapes, mass in zip(LINK_NAMES, model.link_shapes, model.link_masses_kg, strict=True):
        _link(robot, name, shapes, mass, _ARM_COLOUR[0])
    for parent, child, spec in zip(LINK_NAMES[:-1], LINK_NAMES[1:], model.joints, strict=True):
        joint = ET.SubElement(robot, "joint", name=spec.name, type="revolute")
        ET.SubElement(joint, "parent", link=parent)
        ET.SubElement(joint, "child", link=child)
        ET.SubElement(joint, "origin", xyz=_vec(spec.origin_xyz), rpy="0 0 0")
        ET.SubElement(joint, "axis", xyz=_AXES[spec.axis])
        ET.SubElement(
            joint,
            "limit",
            lower=_fmt(spec.lower),
            upper=_fmt(spec.upper),
            effort=_fmt(spec.max_effort),
            velocity=_fmt(spec.max_velocity),
        )

    tool = model.tool
    _link(robot, FLANGE_LINK, (), _FRAME_MASS_KG, _ARM_COLOUR[0])
    _link(robot, GRIPPER_LINK, tool.collision_boxes, tool.mass_kg, _TOOL_COLOUR[0])
    _link(robot, TCP_LINK, (), _FRAME_MASS_KG, _TOOL_COLOUR[0])
    _fixed_joint(robot, "joint_flange", LINK_NAMES[-1], FLANGE_LINK, T_LINK6_FLANGE)
    _fixed_joint(robot, "joint_gripper", FLANGE_LINK, GRIPPER_LINK, np.eye(4))
    _fixed_joint(robot, "joint_tcp", GRIPPER_LINK, TCP_LINK, tool.T_flange_tcp)

    ET.indent(robot, space="  ")
    comment = (
        f"<!-- {model.name} with {tool.name}: generated by sdi.robot.urdf from robots.md; "
        f"base frame = robot base (place it at T_world_base); lengths m, angles rad -->\n"
    )
    return '<?xml version="1.0"?>\n' + comment + ET.tostring(robot, encoding="unicode") + "\n"


def write_urdf(model: RobotModel, directory: str | Path) -> Path:
    """Write ``<directory>/<model.name>.urdf`` (creating `directory`) and return its path."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / f"{model.name}.urdf"
    path.write_text(urdf_xml(model), encoding="utf-8")
    return path


__all__ = ["FLANGE_LINK", "GRIPPER_LINK", "TCP_LINK", "urdf_xml", "write_urdf"]
