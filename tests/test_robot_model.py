"""Robot and tool models: public surface, validation messages, tool geometry, URDF content."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import sdi.robot
from sdi.errors import SDIError
from sdi.robot import (
    LINK_NAMES,
    CollisionShape,
    JointSpec,
    RobotModelError,
    default_robots,
    irb120,
    irb1600,
    make_transform,
    two_fg7,
    urdf_xml,
    vgc10,
)


def test_all_lists_the_public_names():
    public = {n for n in dir(sdi.robot) if not n.startswith("_")}
    modules = {"exceptions", "kinematics", "model", "transforms", "urdf"}
    assert set(sdi.robot.__all__) == public - modules


def test_robot_errors_are_sdi_errors():
    assert issubclass(RobotModelError, SDIError)


def test_joint_spec_names_the_joint_and_bound():
    with pytest.raises(RobotModelError, match=r"joint_3\.lower.*1\.5 rad.*-1\.0 rad"):
        JointSpec("joint_3", (0.0, 0.0, 0.0), "y", 1.5, -1.0, 1.0, 1.0)
    with pytest.raises(RobotModelError, match=r"joint_2\.max_velocity"):
        JointSpec("joint_2", (0.0, 0.0, 0.0), "y", -1.0, 1.0, 0.0, 1.0)


def test_robot_model_rejects_a_non_rigid_base():
    with pytest.raises(RobotModelError, match=r"irb120\.T_world_base"):
        irb120(np.diag([2.0, 1.0, 1.0, 1.0]))


def test_two_fg7_opening_is_bounded():
    with pytest.raises(RobotModelError, match=r"2FG7\.opening.*0\.073"):
        two_fg7(opening=0.09)
    closed = two_fg7(opening=0.05)
    inner = [b.T_link_shape[0, 3] - b.half_extents[0] for b in closed.collision_boxes[1:]]
    assert max(inner) == pytest.approx(0.025)


@pytest.mark.parametrize(("tool", "reach"), [(vgc10(), 0.1115), (two_fg7(), 0.140)])
def test_tcp_lies_on_the_flange_z_axis(tool, reach):
    np.testing.assert_allclose(tool.T_flange_tcp[:3, 3], (0.0, 0.0, reach))
    np.testing.assert_allclose(tool.T_flange_tcp[:3, :3], np.eye(3))
    tips = max(b.T_link_shape[2, 3] + b.half_extents[2] for b in tool.collision_boxes)
    assert tips >= reach  # the cups or fingertips reach the TCP


def test_limits_and_rates_follow_robots_md():
    small, big = irb120(), irb1600()
    assert small.joints[5].upper == pytest.approx(6.98132)
    assert small.joints[4].upper == pytest.approx(math.radians(115))
    np.testing.assert_allclose(small.max_acceleration, [0.87266] * 3 + [1.11701] * 2 + [1.46608])
    assert big.joints[2].lower == pytest.approx(-4.27601)
    np.testing.assert_allclose(big.max_acceleration, 0.2 * big.max_velocity)
    assert (small.controller_rate_hz, big.controller_rate_hz) == (50.0, 250.0)


def test_collision_shape_constructors():
    box = CollisionShape.box((-0.1, -0.2, 0.0), (0.3, 0.2, 0.5))
    assert box.half_extents == pytest.approx((0.2, 0.2, 0.25))
    np.testing.assert_allclose(box.T_link_shape[:3, 3], (0.1, 0.0, 0.25))
    cyl = CollisionShape.cylinder("x", 0.05, 0.1, 0.3)
    np.testing.assert_allclose(cyl.T_link_shape[:3, 2], (1.0, 0.0, 0.0), atol=1e-12)
    np.testing.assert_allclose(cyl.T_link_shape[:3, 3], (0.2, 0.0, 0.0))
    with pytest.raises(RobotModelError, match="upper"):
        CollisionShape.box((0.0, 0.0, 0.0), (0.1, -0.1, 0.1))


def test_placed_and_with_tool_make_new_values():
    model = irb120()
    moved = model.placed(make_transform((1.0, 2.0, 0.0)))
    assert moved is not model and model.T_world_base[0, 3] == 0.0
    np.testing.assert_allclose(moved.T_base_world[:3, 3], (-1.0, -2.0, 0.0))
    assert model.with_tool(two_fg7()).tool.kind == "parallel"
    with pytest.raises(ValueError, match="read-only"):
        model.T_world_base[0, 3] = 1.0


@pytest.mark.parametrize("name", ["irb120", "irb1600"])
def test_urdf_tree(name):
    model = default_robots()[name]
    root = ET.fromstring(urdf_xml(model).split("\n", 2)[2])
    links = [link.get("name") for link in root.iter("link")]
    assert links == [*LINK_NAMES, "flange", "gripper", "tcp"]
    revolute = [j for j in root.iter("joint") if j.get("type") == "revolute"]
    assert [j.get("name") for j in revolute] == list(model.joint_names)
    for joint, spec in zip(revolute, model.joints, strict=True):
        limit = joint.find("limit")
        assert limit is not None
        assert float(limit.get("lower", "nan")) == spec.lower
        assert float(limit.get("velocity", "nan")) == spec.max_velocity
    for link in root.iter("link"):
        assert link.find("inertial") is not None  # no simulator-invented 1 kg defaults
