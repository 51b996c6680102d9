"""Does a layout stand? Assemble it in PyBullet, part by part in its sequence, and look.

No robots: each part appears at its design pose (plus a random placement error of up to
`jitter` in x and y, and lifted by `drop` so it never starts inside its support), is let go,
and the scene settles for `settle_each` seconds before the next part; after the last part it
settles for `settle_final` seconds. The layout *stands* when every part ends within
`tolerance` (m) and `max_tilt` (degrees) of its design pose. Parts are boxes with the
simulator's density and friction (`SimDriver`'s defaults), the table is a fixed box.

The step is 1/960 s (the executing simulator, `sdi.execute.sim`, runs at 1 kHz). At 1/240 s
the solver itself moved tall side-by-side columns: a ring of cubes 7 high assembled with no
placement error at all ended with a cube 4.5 mm off, and with 1 mm jitter a wall 4 long and 7
high failed on both seeds tried — parts that stand still on a real table. At 1/480 s the ring 7
high stands, but a ring 10 high still leaned past 3° on one seed of two; at 1/960 s both stand
(worst 1.7 mm, 0.6°). Every stability case that must fall still falls at this rate
(`sdi.bench.stability_cases`, tests). Each part settles 0.15 s: with 0.075 s a load placed
before its counterweight had not yet tipped when the counterweight arrived and "stood".

This is the physics column of the benchmark and the test oracle for the Inspector's
stability check; it is not on the verification path (it takes ~0.2 s of CPU per part).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import pybullet as pb

from sdi.model.layout import Layout

DENSITY = 700.0
FRICTION = 0.9


@dataclass
class Standing:
    """The outcome of one physical assembly."""

    stands: bool
    worst_part: str | None
    worst_offset_m: float
    worst_tilt_deg: float
    fell_at_step: int | None = None
    """First step (1-based) after which some placed part was out of tolerance, when tracked."""
    offsets: dict[str, float] = field(default_factory=dict)

    def to_json_dict(self) -> dict[str, object]:
        return {
            "stands": self.stands,
            "worst_part": self.worst_part,
            "worst_offset_mm": round(self.worst_offset_m * 1000, 2),
            "worst_tilt_deg": round(self.worst_tilt_deg, 2),
            "fell_at_step": self.fell_at_step,
        }


def _tilt_deg(q_xyzw: Sequence[float], q0_xyzw: Sequence[float]) -> float:
    """Angle between two orientations, degrees."""
    dot = abs(sum(a * b for a, b in zip(q_xyzw, q0_xyzw, strict=True)))
    return math.degrees(2 * math.acos(min(1.0, dot)))


def assemble(
    layout: Layout,
    sequence: Sequence[str] | None = None,
    *,
    seed: int = 0,
    jitter: float = 0.001,
    drop: float = 0.0005,
    settle_each: float = 0.15,
    settle_final: float = 1.0,
    tolerance: float = 0.005,
    max_tilt: float = 3.0,
    hz: float = 960.0,
    track_steps: bool = True,
) -> Standing:
    """Place the parts of `layout` in `sequence` (layout order when None) and settle."""
    order = list(sequence) if sequence is not None else list(layout.ids)
    parts = {p.id: p for p in layout.objects}
    rng = np.random.default_rng(seed)
    c = pb.connect(pb.DIRECT)
    try:
        pb.setGravity(0, 0, -9.81, physicsClientId=c)
        pb.setTimeStep(1.0 / hz, physicsClientId=c)
        pb.setPhysicsEngineParameter(numSolverIterations=150, physicsClientId=c)
        table_shape = pb.createCollisionShape(
            pb.GEOM_BOX, halfExtents=[5.0, 5.0, 0.05], physicsClientId=c
        )
        table = pb.createMultiBody(0, table_shape, basePosition=[0, 0, -0.05], physicsClientId=c)
        pb.changeDynamics(table, -1, lateralFriction=FRICTION, physicsClientId=c)
        bodies: dict[str, int] = {}
        design: dict[str, tuple[np.ndarray, tuple[float, ...]]] = {}
        fell_at: int | None = None

        def worst() -> tuple[str | None, float, float, bool]:
            name, off, tilt, ok = None, 0.0, 0.0, True
            for pid, body in bodies.items():
                pos, orn = pb.getBasePositionAndOrientation(body, physicsClientId=c)
                p0, q0 = design[pid]
                d = float(np.linalg.norm(np.array(pos) - p0))
                t = _tilt_deg(orn, q0)
                bad = d > tolerance or t > max_tilt
                if bad:
                    ok = False
                if name is None or (d / tolerance + t / max_tilt) > (
                    off / tolerance + tilt / max_tilt
                ):
                    name, off, tilt = pid, d, t
            return name, off, tilt, ok

        for step, pid in enumerate(order, start=1):
            part = parts[pid]
            w, x, y, z = part.orientation
            q = (x, y, z, w)
            p0 = np.array(part.position, dtype=float)
            design[pid] = (p0, q)
            dxy = rng.uniform(-jitter, jitter, size=2)
            start = [p0[0] + dxy[0], p0[1] + dxy[1], p0[2] + drop]
            shape = pb.createCollisionShape(
                pb.GEOM_BOX, halfExtents=[s / 2 for s in part.size], physicsClientId=c
            )
            mass = DENSITY * part.size[0] * part.size[1] * part.size[2]
            body = pb.createMultiBody(
                mass, shape, basePosition=start, baseOrientation=q, physicsClientId=c
            )
            pb.changeDynamics(body, -1, lateralFriction=FRICTION, physicsClientId=c)
            bodies[pid] = body
            for _ in range(int(settle_each * hz)):
                pb.stepSimulation(physicsClientId=c)
            if track_steps and fell_at is None and not worst()[3]:
                fell_at = step
        for _ in range(int(settle_final * hz)):
            pb.stepSimulation(physicsClientId=c)
        name, off, tilt, ok = worst()
        offsets = {}
        for pid, body in bodies.items():
            pos, _ = pb.getBasePositionAndOrientation(body, physicsClientId=c)
            offsets[pid] = float(np.linalg.norm(np.array(pos) - design[pid][0]))
        return Standing(
            stands=ok,
            worst_part=name,
            worst_offset_m=off,
            worst_tilt_deg=tilt,
            fell_at_step=fell_at,
            offsets=offsets,
        )
    finally:
        pb.disconnect(c)
