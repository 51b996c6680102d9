"""Errors of the robot package, all under the project root `sdi.errors.SDIError`.

Each error names the robot and joint (or field) at fault, the bound it broke and how to fix it.
"""

from __future__ import annotations

from sdi.errors import SDIError


class RobotModelError(SDIError):
    """A robot or tool model is malformed: bad limits, wrong joint count, not a rigid transform.

    `field` names the offending value (``irb120.joint_3.lower``) when known.
    """

    def __init__(self, message: str, *, field: str | None = None) -> None:
        self.field = field
        super().__init__(f"{field}: {message}" if field else message)


class JointLimitError(RobotModelError):
    """A joint value lies outside its limits.

    Attributes name the robot, the joint, the value (rad) and the bound (rad) it broke.
    """

    def __init__(self, robot: str, joint: str, value: float, lower: float, upper: float) -> None:
        self.robot = robot
        self.joint = joint
        self.value = value
        self.lower = lower
        self.upper = upper
        side = "below lower" if value < lower else "above upper"
        bound = lower if value < lower else upper
        super().__init__(
            f"{value:.6f} rad is {side} limit {bound:.6f} rad (range {lower:.6f} … {upper:.6f}); "
            "choose another IK branch or a target the arm reaches inside its range",
            field=f"{robot}.{joint}",
        )
