"""Robot models of the cell: ABB IRB120 + VGC10 and IRB1600 + 2FG7, kinematics, URDF export.

- `model`: joints, tools, OPW parameters and the two arms' factories (`irb120`, `irb1600`),
  placed in the cell by `default_robots`.
- `kinematics`: `fk`/`link_frames` from the URDF chain, analytic `ik`/`ik_nearest` (OPW).
- `urdf`: `urdf_xml`/`write_urdf` for simulators and viewers.

Transforms are named ``T_a_b`` (pose of b in a), lengths are metres, angles radians.
"""

from sdi.robot.exceptions import JointLimitError, RobotModelError
from sdi.robot.kinematics import fk, fk_flange, fk_opw, ik, ik_nearest, link_frames
from sdi.robot.model import (
    IRB120_BASE_XY,
    IRB1600_BASE_XY,
    LINK_NAMES,
    T_LINK6_FLANGE,
    CollisionShape,
    JointSpec,
    OPWParameters,
    RobotModel,
    ToolModel,
    default_robots,
    irb120,
    irb1600,
    robots_for,
    two_fg7,
    vgc10,
)
from sdi.robot.transforms import (
    invert_transform,
    make_transform,
    pose_error,
    rpy_from_matrix,
    tool_down_pose,
)
from sdi.robot.urdf import FLANGE_LINK, GRIPPER_LINK, TCP_LINK, urdf_xml, write_urdf

__all__ = [
    "FLANGE_LINK",
    "GRIPPER_LINK",
    "IRB120_BASE_XY",
    "IRB1600_BASE_XY",
    "LINK_NAMES",
    "TCP_LINK",
    "T_LINK6_FLANGE",
    "CollisionShape",
    "JointLimitError",
    "JointSpec",
    "OPWParameters",
    "RobotModel",
    "RobotModelError",
    "ToolModel",
    "default_robots",
    "fk",
    "fk_flange",
    "fk_opw",
    "ik",
    "ik_nearest",
    "invert_transform",
    "irb120",
    "irb1600",
    "link_frames",
    "make_transform",
    "pose_error",
    "robots_for",
    "rpy_from_matrix",
    "tool_down_pose",
    "two_fg7",
    "urdf_xml",
    "vgc10",
    "write_urdf",
]
