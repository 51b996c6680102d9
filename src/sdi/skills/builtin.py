"""The registered skills: verification (composite and granular), sequencing, recovery, the
parametric generators and the rule-based Specifier, all as tool-callable `Skill`s."""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from sdi.design.composer import compose
from sdi.design.shapes import FAMILIES
from sdi.errors import SequencingError
from sdi.inspector import verifier as V
from sdi.inspector.analysis import Analysis
from sdi.inspector.sequencer import sequence as run_sequence
from sdi.inspector.violation import Violation
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.region import Region
from sdi.recovery import flatten, shift
from sdi.skills.registry import SkillRegistry
from sdi.skills.skill import Skill, SkillResult
from sdi.spec import parse_command
from sdi.spec.structure_spec import STRUCTURE_TYPES, Spec, StructureSpec, structure


class _Args(BaseModel):
    model_config = ConfigDict(extra="forbid")


class LayoutArgs(_Args):
    layout: Layout = Field(
        description="{objects: [{id, position [x,y,z] m, orientation [w,x,y,z], "
        "size [sx,sy,sz] m}]}"
    )
    sequence: list[str] | None = Field(
        None, description="assembly order by part id; omit to let the sequencer choose"
    )


class SequenceArgs(_Args):
    layout: Layout
    precedence: list[tuple[str, str]] = Field(
        default_factory=list, description="(before, after) id pairs"
    )


class FlattenArgs(_Args):
    layout: Layout
    z_max: float | None = Field(None, gt=0, description="height limit for every part's top, m")
    blocked: list[Region] = Field(default_factory=list, description="regions to keep out of")


class ShiftArgs(_Args):
    layout: Layout
    blocked: list[Region] = Field(default_factory=list, description="regions to move out of")
    dx: float | None = Field(None, description="explicit move along x, m")
    dy: float | None = Field(None, description="explicit move along y, m")


class SpecifyArgs(_Args):
    command: str = Field(description="the operator's plain-language command")


class GenerateArgs(_Args):
    structures: list[StructureSpec] = Field(min_length=1, description="structures to build")


def _layout_data(
    layout: Layout, violations: list[Violation] | tuple[Violation, ...]
) -> dict[str, Any]:
    return {
        "layout": layout.to_json_dict(),
        "passed": not violations,
        "violations": [v.to_json_dict() for v in violations],
    }


def _checked(layout: Layout, cell: CellConfig, **extra: Any) -> SkillResult:
    report = V.verify(layout, cell)
    data = (
        _layout_data(layout, report.violations) | {"sequence": list(report.sequence or [])} | extra
    )
    return SkillResult(
        status="success" if report.passed else "partial",
        data=data,
        errors=tuple(
            f"{v.constraint.value}: {v.message} — {v.hint}" for v in report.violations[:10]
        ),
    )


def _granular(
    name: str, description: str, checks: list[Any], order: str | None, cell: CellConfig
) -> Skill[LayoutArgs]:
    def run(args: LayoutArgs) -> SkillResult:
        a = Analysis(args.layout, cell)
        found: list[Violation] = []
        for check in checks:
            found.extend(check(a))
        if order:
            order_v, _ = V.order_violations(a, args.sequence)
            found.extend(v for v in order_v if v.constraint.value in order.split(","))
        return SkillResult(
            status="success" if not found else "failure",
            data={"passed": not found, "violations": [v.to_json_dict() for v in found]},
            errors=tuple(f"{v.message} — {v.hint}" for v in found[:10]),
        )

    return Skill(name, description, LayoutArgs, run)


SHAPE_HELP = {
    "tower": "a single column; height = levels",
    "row": "parts side by side on the table; length = parts, gap_m optional",
    "grid": "one flat layer length × width (or count parts)",
    "wall": "a vertical wall one part thick; length × height",
    "block": "a solid box length × width × height",
    "pack": "count parts as compact as possible",
    "pyramid": "base length, dims 2 (a face) or 3 (square), height ≤ base",
    "staircase": "steps columns rising by one; width parts across",
    "bridge": "pillars height high joined by beams; span gap in parts (1–2); spans",
    "arch": "two pillars, corbels and a beam; span = opening in parts (1–3)",
    "canopy": "four pillars height high with a closed two-layer beam roof; span 1–2",
    "enclosure": "a hollow ring length × width, height levels",
    "castle": "an enclosure with corner towers count levels higher",
    "l_shape": "an L with arms length and width",
    "u_shape": "a U: base length, arms width",
    "t_shape": "a T: bar length, stem width",
    "cross": "a plus sign with arms; length = overall size",
}


def default_registry(cell: CellConfig | None = None) -> SkillRegistry:
    """Every skill of §III-B bound to `cell`."""
    cell = cell or CellConfig()

    def verify(args: LayoutArgs) -> SkillResult:
        report = V.verify(args.layout, cell, sequence=args.sequence)
        return SkillResult(
            status="success" if report.passed else "failure",
            data=report.to_json_dict(),
            errors=tuple(
                f"{v.constraint.value}: {v.message} — {v.hint}" for v in report.violations[:20]
            ),
        )

    def sequence(args: SequenceArgs) -> SkillResult:
        try:
            order = run_sequence(Analysis(args.layout, cell, tuple(args.precedence)))
        except SequencingError as exc:
            return SkillResult.fail(str(exc), blocked=exc.blocked)
        return SkillResult.ok(sequence=order)

    def do_flatten(args: FlattenArgs) -> SkillResult:
        return _checked(
            flatten(args.layout, cell, z_max=args.z_max, blocked=tuple(args.blocked)), cell
        )

    def do_shift(args: ShiftArgs) -> SkillResult:
        return _checked(
            shift(args.layout, cell, blocked=tuple(args.blocked), dx=args.dx, dy=args.dy), cell
        )

    def specify(args: SpecifyArgs) -> SkillResult:
        spec = parse_command(args.command, cell)
        return SkillResult.ok(spec=spec.model_dump(mode="json", exclude_none=True))

    def generate(args: GenerateArgs) -> SkillResult:
        return _checked(compose(Spec(structures=tuple(args.structures)), cell), cell)

    skills: list[Skill[Any]] = [
        Skill(
            "verify",
            "Check a layout against every constraint (workspace, collision, contact, "
            "support, stability, gravity, sequence, gripping); returns violations with hints.",
            LayoutArgs,
            verify,
        ),
        _granular(
            "check_workspace",
            "Check only that every part lies inside the workspace.",
            [V.check_workspace],
            None,
            cell,
        ),
        _granular(
            "check_collision",
            "Check only that no two parts overlap.",
            [V.check_collision],
            None,
            cell,
        ),
        _granular(
            "check_gravity",
            "Check support: nothing floats, every part rests on a top "
            "face, sub-structures are stable, lower parts are placed first.",
            [V.check_contact, V.check_support, V.check_stability],
            "gravity,sequence",
            cell,
        ),
        _granular(
            "check_gripping",
            "Check that a gripper can grip each part when it is placed.",
            [],
            "gripping",
            cell,
        ),
        Skill(
            "sequence",
            "Assembly order for a layout (bottom-up, grippable), or the parts that "
            "block every order.",
            SequenceArgs,
            sequence,
        ),
        Skill(
            "flatten",
            "Recovery: lower the structure under z_max by moving top parts beside it.",
            FlattenArgs,
            do_flatten,
        ),
        Skill(
            "shift",
            "Recovery: move the whole structure by (dx, dy) or out of blocked regions.",
            ShiftArgs,
            do_shift,
        ),
        Skill(
            "specify",
            "Turn a plain-language command into a structured specification.",
            SpecifyArgs,
            specify,
        ),
        Skill(
            "generate",
            "Build a layout from structure specifications (shape and parameters).",
            GenerateArgs,
            generate,
        ),
    ]
    for shape in FAMILIES:
        skills.append(_generator(shape, cell))
    return SkillRegistry(skills)


def _generator(shape: str, cell: CellConfig) -> Skill[Any]:
    """`generate_<shape>`: its arguments are the family's own slots and placement."""
    fields = {k: v for k, v in STRUCTURE_TYPES[shape].model_fields.items() if k != "shape"}
    from pydantic import create_model

    params = create_model(  # type: ignore[call-overload]
        f"Generate_{shape}",
        __config__=ConfigDict(extra="forbid"),
        **{k: (f.annotation, f) for k, f in fields.items()},
    )

    def run(args: BaseModel) -> SkillResult:
        spec = structure(shape, **args.model_dump(exclude_unset=True))
        return _checked(compose(Spec(structures=(spec,)), cell), cell)

    return Skill(
        f"generate_{shape}", f"Generate a verified {shape}: {SHAPE_HELP[shape]}.", params, run
    )
