"""Hand-made layouts that are hard for a stability check: cantilevers, overhangs, a canopy with
a pillar missing, beams on one support, counterweights, loads on a tip, a stepped overhang.

Each case carries the answer physics gives (`sdi.execute.physics_check.assemble`, in the
case's `sequence` when it gives one, else in the Inspector's order): `stands`. The Inspector
must refuse every case that falls; `tests/test_stability.py` and `benchmarks/physics_stands.py`
hold it to that.
Units are metres; 5 cm cubes and 15 × 5 × 5 cm beams; the table top is z = 0.
"""

from __future__ import annotations

from dataclasses import dataclass

from sdi.model.layout import Layout
from sdi.model.part import Part, quat_from_yaw

S = 0.05
BEAM = (0.15, 0.05, 0.05)


@dataclass(frozen=True)
class Case:
    name: str
    layout: Layout
    stands: bool
    """What physics says (PyBullet, 1 mm jitter, the Inspector's order)."""
    note: str
    sequence: tuple[str, ...] | None = None
    """The order to check and assemble in (None: the Inspector's own)."""


def _cube(pid: str, x: float, y: float, level: int) -> Part:
    return Part(id=pid, position=(x, y, S / 2 + level * S), size=(S, S, S))


def _beam(pid: str, x: float, y: float, z: float, *, along_y: bool = False) -> Part:
    if along_y:
        return Part(id=pid, position=(x, y, z), size=BEAM, orientation=quat_from_yaw(1.5707963))
    return Part(id=pid, position=(x, y, z), size=BEAM)


def _tower(x: float, y: float, n: int, prefix: str) -> list[Part]:
    return [_cube(f"{prefix}{k + 1}", x, y, k) for k in range(n)]


def _canopy(drop_pillar: bool) -> Layout:
    """The generated 1-high canopy (`sdi plan "a canopy 1 high"`), optionally less pillar c1."""
    parts = [
        _cube("c1", 0.5, 0.25, 0),
        _cube("c2", 0.5, 0.35, 0),
        _cube("c3", 0.4, 0.25, 0),
        _cube("c4", 0.4, 0.35, 0),
        _beam("b1", 0.5, 0.3, 0.075, along_y=True),
        _beam("b2", 0.4, 0.3, 0.075, along_y=True),
        _beam("b3", 0.45, 0.25, 0.125),
        _beam("b4", 0.45, 0.3, 0.125),
        _beam("b5", 0.45, 0.35, 0.125),
    ]
    if drop_pillar:
        parts = parts[1:]
    return Layout(objects=tuple(parts))


def _counterweighted() -> Layout:
    y = 0.3
    return Layout(
        objects=(
            _cube("p", 0.45, y, 0),
            _beam("beam", 0.43, y, 0.075),
            _cube("tip", 0.38, y, 2),
            _cube("weight", 0.48, y, 2),
        )
    )


def cases() -> list[Case]:
    y = 0.3
    out = [
        Case("canopy", _canopy(False), True, "the generated 1-high canopy"),
        Case(
            "canopy_one_pillar_removed",
            _canopy(True),
            False,
            "issue 12: b1 rests on one pillar; the cross beams on it cannot hold it up",
        ),
        Case(
            "cantilever_beam_5cm",
            Layout(objects=(*_tower(0.40, y, 2, "t"), _beam("beam", 0.45, y, 0.125))),
            False,
            "a beam on a tower with its centre 5 cm past the tower's axis",
        ),
        Case(
            "cantilever_beam_2cm",
            Layout(objects=(*_tower(0.40, y, 2, "t"), _beam("beam", 0.42, y, 0.125))),
            True,
            "a beam on a tower, 2 cm off centre: its centre of mass is over the tower",
        ),
        Case(
            "overhanging_cube_3cm",
            Layout(objects=(_cube("a", 0.40, y, 0), _cube("b", 0.43, y, 1))),
            False,
            "a cube 3 cm off the one below",
        ),
        Case(
            "overhanging_cube_1cm",
            Layout(objects=(_cube("a", 0.40, y, 0), _cube("b", 0.41, y, 1))),
            True,
            "a cube 1 cm off the one below",
        ),
        Case(
            "beam_on_one_support_centred",
            Layout(objects=(_cube("a", 0.45, y, 0), _beam("beam", 0.45, y, 0.075))),
            True,
            "a beam balanced on one cube at its middle",
        ),
        Case(
            "beam_on_one_support_at_its_end",
            Layout(objects=(_cube("a", 0.40, y, 0), _beam("beam", 0.45, y, 0.075))),
            False,
            "a beam whose end rests on one cube",
        ),
        Case(
            "beam_centred_tip_load_1",
            Layout(
                objects=(
                    _cube("a", 0.45, y, 0),
                    _beam("beam", 0.45, y, 0.075),
                    _cube("tip", 0.50, y, 2),
                )
            ),
            True,
            "a beam on one cube with a cube on one end: the centre of mass moves 1.25 cm",
        ),
        Case(
            "beam_centred_tip_load_4",
            Layout(
                objects=(
                    _cube("a", 0.45, y, 0),
                    _beam("beam", 0.45, y, 0.075),
                    *[_cube(f"tip{k}", 0.50, y, 2 + k) for k in range(4)],
                )
            ),
            False,
            "four cubes on one end: the centre of mass moves 2.9 cm, past the cube's edge",
        ),
        Case(
            "load_on_a_part_that_overhangs",
            Layout(
                objects=(
                    _cube("a", 0.40, y, 0),
                    _cube("b", 0.42, y, 1),
                    _beam("beam", 0.42, y, 0.125),
                    _cube("c", 0.48, y, 3),
                )
            ),
            False,
            "each part over its own support; b, the beam and c together are not",
        ),
        Case(
            "stepped_overhang",
            Layout(
                objects=(
                    _cube("s1", 0.40, y, 0),
                    _cube("s2", 0.42, y, 1),
                    _cube("s3", 0.44, y, 2),
                    _cube("s4", 0.46, y, 3),
                )
            ),
            False,
            "cubes stepped 2 cm per level: each on its own support, the upper three not",
        ),
        Case(
            "straddle",
            Layout(
                objects=(_cube("a", 0.40, y, 0), _cube("b", 0.45, y, 0), _cube("c", 0.425, y, 1))
            ),
            True,
            "a cube on two cubes, across their joint",
        ),
        Case(
            "bridge",
            Layout(
                objects=(
                    *_tower(0.40, y, 2, "t"),
                    *_tower(0.50, y, 2, "u"),
                    _beam("beam", 0.45, y, 0.125),
                )
            ),
            True,
            "a beam on two towers",
        ),
        Case(
            "counterweight_after_the_load",
            _counterweighted(),
            False,
            "a beam 2 cm off its one support; the operator's order puts the load on the long end "
            "before the counterweight, so the beam tips in between",
            sequence=("p", "beam", "tip", "weight"),
        ),
        Case(
            "counterweight_order_by_the_inspector",
            _counterweighted(),
            True,
            "the same layout in the Inspector's order: the preferred order (by x) puts the load "
            "first and falls, so the Inspector moves the counterweight before it",
        ),
        Case(
            "counterweight_before_the_load",
            Layout(
                objects=(
                    _cube("p", 0.45, y, 0),
                    _beam("beam", 0.47, y, 0.075),
                    _cube("weight", 0.42, y, 2),
                    _cube("tip", 0.52, y, 2),
                )
            ),
            True,
            "the same, mirrored: the counterweight goes on first, and the whole stands",
        ),
    ]
    return out
