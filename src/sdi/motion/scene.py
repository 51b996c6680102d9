"""The collision scene ℰ_k for motion planning: robots, table, placed parts, the carried part.

A private PyBullet client in DIRECT mode (no physics stepping; only geometry queries) holds the
robots loaded from the project's URDFs at their cell placements, the table below z = 0, one
box per placed part and the part being carried, which follows the robot's TCP. `collides(q)`
answers whether a robot at configuration q is closer than `margin` to anything it must not
touch: the table, placed parts, the other arm, itself (non-adjacent links), or, for the
carried part, anything but its own gripper.
"""

from __future__ import annotations

import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pybullet as pb

from sdi.model.part import quat_from_matrix
from sdi.robot import RobotModel, fk, write_urdf

TABLE_HALF = (1.5, 1.5, 0.05)
WRIST_FOREARM = 3
"""PyBullet link index of link_4 (joint indices follow the URDF: link_1 is 0)."""
TABLE_CENTRE = (0.55, 0.30, -0.05)


def _quat_xyzw(R: np.ndarray) -> tuple[float, float, float, float]:
    """PyBullet's quaternion order [x, y, z, w] of a rotation matrix."""
    w, x, y, z = quat_from_matrix(R)
    return (x, y, z, w)


@dataclass
class _Loaded:
    model: RobotModel
    body: int
    joints: list[int]
    pairs: list[tuple[int, int]]  # non-adjacent link pairs for self-collision


class Scene:
    """One PyBullet DIRECT client holding the cell's geometry for collision queries."""

    def __init__(self, robots: dict[str, RobotModel], *, margin: float = 0.005) -> None:
        self.margin = margin
        self._margin = margin
        self.client = pb.connect(pb.DIRECT)
        self._dir = tempfile.TemporaryDirectory(prefix="sdi-urdf-")
        self.robots: dict[str, _Loaded] = {}
        c = self.client
        table = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=TABLE_HALF, physicsClientId=c)
        self.table = pb.createMultiBody(0, table, basePosition=TABLE_CENTRE, physicsClientId=c)
        for name, model in robots.items():
            path = write_urdf(model, Path(self._dir.name) / name)
            T = model.T_world_base
            body = pb.loadURDF(
                str(path),
                basePosition=T[:3, 3].tolist(),
                baseOrientation=_quat_xyzw(T[:3, :3]),
                useFixedBase=True,
                physicsClientId=c,
            )
            joints = [
                j
                for j in range(pb.getNumJoints(body, physicsClientId=c))
                if pb.getJointInfo(body, j, physicsClientId=c)[2] == pb.JOINT_REVOLUTE
            ]
            # frames without geometry (flange, tcp) cannot collide
            links = [
                k
                for k in range(-1, pb.getNumJoints(body, physicsClientId=c))
                if pb.getCollisionShapeData(body, k, physicsClientId=c)
            ]
            # SRDF-style: adjacent links, and the forearm (link 4) with everything past the
            # spherical wrist, are not checked; their boxes overlap at ordinary wrist angles.
            pairs = [(a, b) for a in links for b in links if b - a >= 3 and a != WRIST_FOREARM]
            self.robots[name] = _Loaded(model, body, joints, pairs)
        self.parts: dict[str, int] = {}  # part id → link index in the compound body
        self._placed: list[tuple[str, np.ndarray, tuple[float, float, float]]] = []
        self._parts_body = -1
        self.carried: dict[str, tuple[int, np.ndarray]] = {}  # robot → (body, T_tcp_part)

    def close(self) -> None:
        if self.client >= 0:
            pb.disconnect(self.client)
            self.client = -1
        self._dir.cleanup()

    def __enter__(self) -> Scene:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- scene edits ---------------------------------------------------------------------------
    def _box(self, size: tuple[float, float, float]) -> int:
        half = [s / 2 for s in size]
        shape = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=half, physicsClientId=self.client)
        return pb.createMultiBody(0, shape, physicsClientId=self.client)

    def add_part(
        self, part_id: str, T_world_part: np.ndarray, size: tuple[float, float, float]
    ) -> None:
        """A placed part: a static obstacle from now on.

        All placed parts are links of one static compound body, so a collision query against
        them is one call whatever their number.
        """
        self._placed.append((part_id, T_world_part.copy(), size))
        c = self.client
        if self._parts_body >= 0:
            pb.removeBody(self._parts_body, physicsClientId=c)
        shapes = [
            pb.createCollisionShape(pb.GEOM_BOX, halfExtents=[v / 2 for v in sz], physicsClientId=c)
            for _, _, sz in self._placed
        ]
        n = len(shapes)
        self._parts_body = pb.createMultiBody(
            baseMass=0, baseCollisionShapeIndex=-1, basePosition=[0, 0, 0],
            linkMasses=[0] * n, linkCollisionShapeIndices=shapes, linkVisualShapeIndices=[-1] * n,
            linkPositions=[T[:3, 3].tolist() for _, T, _ in self._placed],
            linkOrientations=[_quat_xyzw(T[:3, :3]) for _, T, _ in self._placed],
            linkInertialFramePositions=[[0, 0, 0]] * n,
            linkInertialFrameOrientations=[[0, 0, 0, 1]] * n,
            linkParentIndices=[0] * n, linkJointTypes=[pb.JOINT_FIXED] * n,
            linkJointAxis=[[0, 0, 1]] * n, physicsClientId=c,
        )  # fmt: skip
        self.parts = {pid: k for k, (pid, _, _) in enumerate(self._placed)}

    def near_parts(self, body: int, distance: float, link: int | None = None) -> set[str]:
        """Placed parts within `distance` (m) of `body` (or one of its links)."""
        if self._parts_body < 0:
            return set()
        kwargs = {} if link is None else {"linkIndexA": link}
        points = pb.getClosestPoints(
            body, self._parts_body, distance, physicsClientId=self.client, **kwargs
        )
        return {self._placed[p[4]][0] for p in points if 0 <= p[4] < len(self._placed)}

    def attach(self, robot: str, T_tcp_part: np.ndarray, size: tuple[float, float, float]) -> None:
        """`robot` carries a part of `size` at T_tcp_part until `detach`."""
        self.detach(robot)
        self.carried[robot] = (self._box(size), T_tcp_part)

    def detach(self, robot: str) -> None:
        held = self.carried.pop(robot, None)
        if held is not None:
            pb.removeBody(held[0], physicsClientId=self.client)

    def set_q(self, robot: str, q: np.ndarray) -> None:
        r = self.robots[robot]
        for j, v in zip(r.joints, q, strict=True):
            pb.resetJointState(r.body, j, float(v), physicsClientId=self.client)
        held = self.carried.get(robot)
        if held is not None:
            T = fk(r.model, q) @ held[1]
            pb.resetBasePositionAndOrientation(
                held[0], T[:3, 3].tolist(), _quat_xyzw(T[:3, :3]), physicsClientId=self.client
            )

    # -- queries ------------------------------------------------------------------------------
    def _near(self, a: int, b: int, link_a: int | None = None) -> bool:
        kwargs = {} if link_a is None else {"linkIndexA": link_a}
        return bool(pb.getClosestPoints(a, b, self._margin, physicsClientId=self.client, **kwargs))

    def collides(
        self,
        robot: str,
        q: np.ndarray,
        *,
        ignore_parts: frozenset[str] = frozenset(),
        margin: float | None = None,
    ) -> str | None:
        """What robot `robot` at q would hit (a short description), or None when it is clear.

        `ignore_parts` are placed parts the gripper and carried part may touch (the support a
        part is being set down on; "table" lets the carried part touch the table top);
        `margin` overrides the clearance (m) for close work.
        """
        self._margin = self.margin if margin is None else margin
        self.set_q(robot, q)
        r = self.robots[robot]
        c = self.client
        # every moving link against the table (the base, link −1, stands on it)
        on_table = pb.getClosestPoints(r.body, self.table, self._margin, physicsClientId=c)
        if any(p[3] != -1 for p in on_table):
            return "table"
        hit = sorted(self.near_parts(r.body, self._margin) - ignore_parts)
        if hit:
            return f"part {hit[0]}"
        for name, other in self.robots.items():
            if name != robot and self._near(r.body, other.body):
                return f"robot {name}"
        for a, b in r.pairs:
            if pb.getClosestPoints(
                r.body, r.body, 0.0, linkIndexA=a, linkIndexB=b, physicsClientId=c
            ):
                return "itself"
        held = self.carried.get(robot)
        if held is not None:
            box = held[0]
            if "table" not in ignore_parts and self._near(box, self.table):
                return "table (carried part)"
            hit = sorted(self.near_parts(box, self._margin) - ignore_parts)
            if hit:
                return f"part {hit[0]} (carried part)"
            for name, other in self.robots.items():
                if name != robot and self._near(box, other.body):
                    return f"robot {name} (carried part)"
        return None
