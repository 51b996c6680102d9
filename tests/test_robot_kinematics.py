"""Kinematics of the cell's arms: FK against robots.md, OPW IK round trips, limits, reach, URDF.

Poses are 4×4 ``T_a_b`` (pose of b in a), metres and radians. Random joint vectors are drawn
uniformly inside each robot's limits with a fixed seed.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from sdi.robot import (
    TCP_LINK,
    JointLimitError,
    RobotModel,
    default_robots,
    fk,
    fk_flange,
    fk_opw,
    ik,
    ik_nearest,
    link_frames,
    pose_error,
    tool_down_pose,
    write_urdf,
)

ROBOTS = default_robots()
NAMES = sorted(ROBOTS)
POSE_TOL = 1e-6  # m and rad


def _random_q(model: RobotModel, n: int, seed: int) -> np.ndarray:
    return np.random.default_rng(seed).uniform(model.lower, model.upper, size=(n, 6))


def _assert_pose(T_a: np.ndarray, T_b: np.ndarray, tol: float = POSE_TOL) -> None:
    dp, dr = pose_error(T_a, T_b)
    assert dp < tol and dr < tol, f"pose differs by {dp:.3g} m, {dr:.3g} rad"


@pytest.fixture(params=NAMES)
def robot(request: pytest.FixtureRequest) -> RobotModel:
    return ROBOTS[request.param]


# -- forward kinematics ----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "flange_xyz"), [("irb120", (0.374, 0.0, 0.630)), ("irb1600", (0.815, 0.0, 1.1865))]
)
def test_flange_at_zero_matches_robots_md(name: str, flange_xyz: tuple[float, float, float]):
    model = ROBOTS[name].placed(np.eye(4))
    T = fk_flange(model, np.zeros(6))
    np.testing.assert_allclose(T[:3, 3], flange_xyz, atol=1e-12)
    # tool0 = link 6 turned by rpy (0, π/2, 0): the tool axis z along base x, x pointing down
    np.testing.assert_allclose(T[:3, 2], (1.0, 0.0, 0.0), atol=1e-12)
    np.testing.assert_allclose(T[:3, 0], (0.0, 0.0, -1.0), atol=1e-12)


def test_tcp_is_tool_offset_along_flange_z(robot: RobotModel):
    q = _random_q(robot, 1, seed=1)[0]
    T_flange, T_tcp = fk_flange(robot, q), fk(robot, q)
    offset = {"irb120": 0.1115, "irb1600": 0.140}[robot.name]
    np.testing.assert_allclose(T_tcp[:3, 3], T_flange[:3, 3] + offset * T_flange[:3, 2], atol=1e-12)


def test_link_frames_order_and_base(robot: RobotModel):
    q = _random_q(robot, 1, seed=2)[0]
    frames = link_frames(robot, q)
    assert len(frames) == 9
    np.testing.assert_allclose(frames[0], robot.T_world_base)
    np.testing.assert_allclose(frames[7], fk_flange(robot, q))
    np.testing.assert_allclose(frames[8], fk(robot, q))
    # joint 1 turns about the base z, so link_1 sits at the base origin
    np.testing.assert_allclose(frames[1][:3, 3], robot.T_world_base[:3, 3], atol=1e-12)


def test_opw_fk_equals_urdf_chain(robot: RobotModel):
    """The OPW offsets/sign corrections map the robot's joint values onto the OPW model."""
    at_origin = robot.placed(np.eye(4))
    for q in _random_q(robot, 200, seed=3):
        _assert_pose(fk_opw(robot.opw, q), fk_flange(at_origin, q), tol=1e-12)


def test_irb120_dh_table_of_robots_md_equals_urdf_chain():
    """robots.md's standard DH rows (θ offset, d, a, α) end in tool0 = our flange frame."""

    def dh(theta: float, d: float, a: float, alpha: float) -> np.ndarray:
        ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
        return np.array(
            [
                [ct, -st * ca, st * sa, a * ct],
                [st, ct * ca, -ct * sa, a * st],
                [0, sa, ca, d],
                [0, 0, 0, 1],
            ]
        )

    half = math.pi / 2
    rows = [(0, 0.290, 0, -half), (-half, 0, 0.270, 0), (0, 0, 0.070, -half)]
    rows += [(0, 0.302, 0, half), (0, 0, 0, -half), (math.pi, 0.072, 0, 0)]
    model = ROBOTS["irb120"].placed(np.eye(4))
    for q in _random_q(model, 50, seed=9):
        T = np.eye(4)
        for (offset, d, a, alpha), qi in zip(rows, q, strict=True):
            T = T @ dh(qi + offset, d, a, alpha)
        _assert_pose(T, fk_flange(model, q), tol=1e-12)


# -- inverse kinematics ----------------------------------------------------------------------


def test_fk_ik_round_trip(robot: RobotModel):
    worst = 0.0
    for q in _random_q(robot, 600, seed=4):
        T = fk(robot, q)
        solutions = ik(robot, T)
        assert 1 <= len(solutions) <= 8
        every_turn = ik(robot, T, all_turns=True)
        assert len(every_turn) >= len(solutions)
        for s in every_turn:
            dp, dr = pose_error(fk(robot, s), T)
            worst = max(worst, dp, dr)
            assert robot.within_limits(s, tol=0.0), f"{s} outside the limits"
        # the sampled configuration itself is one of the branches/turns
        gap = np.min(np.max(np.abs(np.array(every_turn) - q), axis=1))
        assert gap < 1e-6, f"q = {q} not among the IK solutions (closest {gap:.3g} rad)"
    assert worst < POSE_TOL


def test_unreachable_poses_give_no_solution(robot: RobotModel):
    base = robot.T_world_base[:3, 3]
    far = tool_down_pose(base + np.array([3.0, 0.0, 0.5]))
    assert ik(robot, far) == []
    assert ik_nearest(robot, far, np.zeros(6)) is None
    above = tool_down_pose(base + np.array([0.0, 0.0, 5.0]))
    assert ik(robot, above, all_turns=True) == []


def test_ik_nearest_returns_the_seed_branch(robot: RobotModel):
    rng = np.random.default_rng(5)
    w = 1.0 / robot.max_velocity
    for q in _random_q(robot, 300, seed=6):
        T = fk(robot, q)
        np.testing.assert_allclose(ik_nearest(robot, T, q), q, atol=1e-7)
        seed = q + rng.normal(0.0, 1e-3, 6)
        best = ik_nearest(robot, T, seed)
        assert best is not None
        _assert_pose(fk(robot, best), T)
        others = [s for s in ik(robot, T, all_turns=True) if np.max(np.abs(s - q)) > 1e-6]
        margin = min((np.sum(((s - seed) * w) ** 2) for s in others), default=np.inf)
        if margin > 10 * np.sum(((q - seed) * w) ** 2):  # branches well apart: must pick q's
            np.testing.assert_allclose(best, q, atol=1e-6)


def test_ik_respects_joint_limits():
    model = ROBOTS["irb120"]
    q = np.array([2.95, 0.3, -0.5, 0.4, 0.8, 0.2])  # joint 1 beyond its 2.87979 rad limit
    assert not model.within_limits(q)
    with pytest.raises(JointLimitError, match=r"irb120\.joint_1.*above upper limit 2\.879790"):
        model.check_limits(q)
    for s in ik(model, fk(model, q), all_turns=True):
        assert model.within_limits(s, tol=0.0)
        assert abs(s[0] - q[0]) > 0.1


def test_multi_turn_joints_offer_every_turn():
    model = ROBOTS["irb1600"]  # joint 4 ±200°, joint 6 ±400°
    q = np.array([0.2, 0.4, -0.3, 0.5, 0.7, 0.1])
    T = fk(model, q)
    turns = [s for s in ik(model, T, all_turns=True) if np.allclose(s[:3], q[:3], atol=1e-9)]
    j6 = sorted({round(float(s[5]), 9) for s in turns if abs(s[3] - q[3]) < 1e-9})
    np.testing.assert_allclose(j6, [q[5] - 2 * math.pi, q[5], q[5] + 2 * math.pi], atol=1e-9)
    far = q + np.array([0, 0, 0, 0, 0, 2 * math.pi])
    np.testing.assert_allclose(ik_nearest(model, T, far), far, atol=1e-9)


def test_wrist_singularity_keeps_the_seeds_joint_4(robot: RobotModel):
    q = np.array([0.3, 0.2, -0.4, 0.8, 0.0, -0.5])  # q5 = 0: axes 4 and 6 aligned
    T = fk(robot, q)
    for s in ik(robot, T):
        _assert_pose(fk(robot, s), T)
    best = ik_nearest(robot, T, q)
    assert best is not None
    np.testing.assert_allclose(best, q, atol=1e-9)


# -- reach in the cell -----------------------------------------------------------------------


CUBE_TOP_GRASP_Z = 0.05  # TCP on the top face of a 0.05 m cube on the table
YAWS = (0.0, math.pi / 4, math.pi / 2, math.pi)


def test_irb120_reaches_the_centre_but_not_beyond_x_06():
    model = ROBOTS["irb120"]
    for yaw in YAWS:
        assert ik(model, tool_down_pose((0.45, 0.30, CUBE_TOP_GRASP_Z), yaw))
        assert not ik(model, tool_down_pose((0.70, 0.30, CUBE_TOP_GRASP_Z), yaw))


def test_irb1600_reaches_the_workspace_corners():
    model = ROBOTS["irb1600"]
    for x in (0.20, 0.80):
        for y in (0.05, 0.55):
            for yaw in (0.0, math.pi / 2):  # the 2FG7 closes along world x or y
                T = tool_down_pose((x, y, CUBE_TOP_GRASP_Z), yaw)
                assert ik(model, T), f"IRB1600 cannot reach ({x}, {y}) at yaw {yaw}"


def test_default_cell_placement():
    irb120, irb1600 = ROBOTS["irb120"], ROBOTS["irb1600"]
    np.testing.assert_allclose(irb120.T_world_base[:3, 3], (0.0, 0.30, 0.0))
    np.testing.assert_allclose(irb120.T_world_base[:3, :3], np.eye(3))  # faces +x
    np.testing.assert_allclose(irb1600.T_world_base[:3, 3], (1.30, 0.30, 0.0))
    np.testing.assert_allclose(irb1600.T_world_base[:3, 0], (-1.0, 0.0, 0.0), atol=1e-12)
    assert (irb120.controller_rate_hz, irb1600.controller_rate_hz) == (50.0, 250.0)
    assert (irb120.tool.kind, irb1600.tool.kind) == ("vacuum", "parallel")


# -- URDF --------------------------------------------------------------------------------------


def test_urdf_loads_in_yourdfpy_and_matches_fk(robot: RobotModel, tmp_path):
    yourdfpy = pytest.importorskip("yourdfpy")
    urdf = yourdfpy.URDF.load(str(write_urdf(robot, tmp_path)))
    assert list(urdf.actuated_joint_names) == list(robot.joint_names)
    for q in _random_q(robot, 25, seed=7):
        urdf.update_cfg(q)
        T_base_tcp = urdf.get_transform(frame_to=TCP_LINK, frame_from="base_link")
        _assert_pose(robot.T_world_base @ T_base_tcp, fk(robot, q), tol=1e-9)


def test_urdf_loads_in_pybullet_and_matches_fk(robot: RobotModel, tmp_path):
    pb = pytest.importorskip("pybullet")
    client = pb.connect(pb.DIRECT)
    try:
        T = robot.T_world_base
        yaw = math.atan2(T[1, 0], T[0, 0])  # the cell's bases are only turned about z
        body = pb.loadURDF(
            str(write_urdf(robot, tmp_path)),
            basePosition=T[:3, 3].tolist(),
            baseOrientation=pb.getQuaternionFromEuler((0.0, 0.0, yaw)),
            useFixedBase=True,
            physicsClientId=client,
        )
        count = pb.getNumJoints(body, physicsClientId=client)
        info = [pb.getJointInfo(body, j, physicsClientId=client) for j in range(count)]
        joint = {i[1].decode(): i[0] for i in info}
        link = {i[12].decode(): i[0] for i in info}
        for q in _random_q(robot, 25, seed=8):
            for name, value in zip(robot.joint_names, q, strict=True):
                pb.resetJointState(body, joint[name], float(value), physicsClientId=client)
            state = pb.getLinkState(
                body, link[TCP_LINK], computeForwardKinematics=True, physicsClientId=client
            )
            T_pb = np.eye(4)
            T_pb[:3, 3] = state[4]
            T_pb[:3, :3] = np.reshape(pb.getMatrixFromQuaternion(state[5]), (3, 3))
            _assert_pose(T_pb, fk(robot, q), tol=1e-6)
    finally:
        pb.disconnect(client)


# -- swept-motion bound (the planner's dense re-check relies on it) --------------------------


def _geometry_points(robot: RobotModel, carried: np.ndarray) -> list[tuple[int, np.ndarray]]:
    """Box corners and cylinder rims of every collision shape, per frame, and a carried part."""
    points = []
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    shapes = [(i, s) for i, ss in enumerate(robot.link_shapes) for s in ss]
    shapes += [(7, b) for b in robot.tool.collision_boxes]
    rim = [(np.cos(a), np.sin(a)) for a in np.linspace(0, 2 * np.pi, 16, endpoint=False)]
    for frame, shape in shapes:
        d = np.array(shape.dimensions)
        if shape.kind == "box":
            local = list(signs * d)
        elif shape.kind == "cylinder":  # rims (radius, half length along z)
            local = [np.array([d[0] * c, d[0] * s, z]) for c, s in rim for z in (-d[-1], d[-1])]
        else:  # sphere: points on the surface
            unit = np.random.default_rng(0).normal(size=(64, 3))
            local = list(d[0] * unit / np.linalg.norm(unit, axis=1, keepdims=True))
        for p in local:
            points.append((frame, (shape.T_link_shape @ np.append(p, 1.0))[:3]))
    points += [(7, p) for p in carried]
    return points


def test_sweep_bound_covers_every_point_of_the_arm_and_its_part(robot: RobotModel):
    from sdi.robot.kinematics import frame_reach, link_frames_batch, sweep_bound

    # a 5 cm cube 4 cm below the flange, as a carried part
    corners = np.array([[x, y, z] for x in (-0.025, 0.025) for y in (-0.025, 0.025)
                        for z in (0.015, 0.065)])  # fmt: skip
    reach = frame_reach(robot, float(np.max(np.linalg.norm(corners, axis=1))))
    points = _geometry_points(robot, corners)
    rng = np.random.default_rng(5)
    qa = _random_q(robot, 200, 11)
    qb = qa + rng.normal(scale=rng.choice([0.001, 0.02, 0.3], size=(200, 1)), size=(200, 6))
    Fa, Fb = link_frames_batch(robot, qa), link_frames_batch(robot, qb)
    for k in range(len(qa)):
        bound = float(sweep_bound(Fa[k], Fb[k][None], reach)[0])
        moved = max(
            np.linalg.norm((Fb[k][f] @ np.append(p, 1))[:3] - (Fa[k][f] @ np.append(p, 1))[:3])
            for f, p in points
        )
        assert moved <= bound + 1e-12
        assert bound < 10 * moved + 1e-3  # and not uselessly loose


def test_link_frames_batch_equals_link_frames(robot: RobotModel):
    from sdi.robot.kinematics import link_frames_batch

    Q = _random_q(robot, 50, 3)
    batch = link_frames_batch(robot, Q)
    for q, frames in zip(Q, batch, strict=True):
        assert np.allclose(np.array(link_frames(robot, q)), frames, atol=1e-12)
