"""Cell configuration files are validated like layouts: finite, ordered, positive, unique,
known keys — each error names the TOML key, the value and the rule it broke."""

from __future__ import annotations

import subprocess
import sys

import pytest

from sdi.errors import InputError
from sdi.model.cell import CellConfig

ROBOT = '[[robots]]\nname = "{name}"\nmodel = "irb120"\nbase_xy = [{x}, 0.3]\n'
AREA = (
    '[[supply_areas]]\nname = "{name}"\nrobot = "{robot}"\nx_range = {xr}\ny_range = [0.0, 0.1]\n'
)


def load(tmp_path, text: str) -> CellConfig:
    path = tmp_path / "cell.toml"
    path.write_text(text)
    return CellConfig.load(path)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("[workspace]\nx_max = inf\n", "workspace.x_max: must be a finite number, got inf"),
        ("[workspace]\nx_max = nan\n", "workspace.x_max: must be a finite number, got nan"),
        ("[workspace]\ny_min = -inf\n", "workspace.y_min: must be a finite number, got -inf"),
        ("[workspace]\nx_min = 0.8\n", "workspace.x_min: must be below x_max (0.8), got 0.8"),
        ("[workspace]\nz_max = -0.1\n", "workspace.z_min: must be below z_max (-0.1), got 0.0"),
        ("[workspace]\nx_max = 1e308\n", "workspace.x_max: must be ≤ 1000.0, got 1e+308"),
        ("[workspace]\nxmax = 0.7\n", "workspace.xmax: unknown key in [workspace]"),
        ("colour = 'red'\n", "colour: unknown key"),
        ("workspace = 1\n", "workspace: must be a TOML table"),
        ("[tolerances]\ncontact = -0.001\n", "tolerances.contact: must be ≥ 0.0, got -0.001"),
        ("[tolerances]\nstability_margin = nan\n", "tolerances.stability_margin: must be a fin"),
        ("[design]\nstructure_gap = -0.1\n", "design.structure_gap: must be ≥ 0.0, got -0.1"),
        ("[design]\nanchor = [0.45, inf]\n", "design.anchor[1]: must be a finite number, got inf"),
        ("[part_types]\ncube = [0.05, 0.05, 0]\n", "part_types.cube[2]: must be > 0.0, got 0"),
        ("[part_types]\ncube = [0.05, 0.05]\n", "part_types.cube: too few numbers in the list"),
        ("[part_types]\ncube = [0.05, 0.05, 'a']\n", "part_types.cube[2]: must be a number"),
        ("[part_types]\nbeam = [0.15, 0.05, 0.05]\n", "part_types must define 'cube'"),
        ("[limits]\nphase_seconds = inf\n", "limits.phase_seconds: must be a finite number"),
        ("[limits]\nmax_parts = 0\n", "limits.max_parts: must be ≥ 1, got 0"),
        (
            ROBOT.format(name="a", x=0.0) + ROBOT.format(name="a", x=1.3),
            "robots[1].name: duplicate name 'a'",
        ),
        (
            AREA.format(name="s", robot="irb120", xr="[0.30, 0.12]"),
            "supply_areas[0].x_range: the first value must be below the second, got [0.3, 0.12]",
        ),
        (
            AREA.format(name="s", robot="irb9000", xr="[0.12, 0.30]"),
            "supply_areas[0].robot: no robot named 'irb9000'",
        ),
        (
            AREA.format(name="s", robot="irb120", xr="[0.12, 0.30]")
            + AREA.format(name="s", robot="irb1600", xr="[0.95, 1.1]"),
            "supply_areas[1].name: duplicate name 's'",
        ),
        ("[[robots]]\nname = 'a'\nmodel = 'irb120'\nbase_xy = [0, nan]\n", "robots[0].base_xy[1]"),
        ("[[robots]]\nname = 'a'\nmodel = 'irb9'\nbase_xy = [0, 0]\n", "robots[0].model"),
    ],
)
def test_bad_values_name_the_key(tmp_path, text, message):
    with pytest.raises(InputError) as info:
        load(tmp_path, text)
    assert message in str(info.value)


@pytest.mark.parametrize(
    "text",
    [
        "",
        "[workspace]\nx_max = 0.7\n",
        "[tolerances]\ncontact = 0\n",  # zero tolerance is allowed, negative is not
        "[part_types]\ncube = [0.04, 0.04, 0.04]\nplate = [0.1, 0.1, 0.01]\n",
        ROBOT.format(name="left", x=0.0),  # the default supply areas name other robots
        AREA.format(name="a", robot="irb120", xr="[0.12, 0.30]")
        + AREA.format(name="b", robot="irb1600", xr="[0.95, 1.10]"),
    ],
)
def test_good_cells_still_load(tmp_path, text):
    assert isinstance(load(tmp_path, text), CellConfig)


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda p: p.mkdir(), "is a folder"),
        (lambda p: p.write_bytes(b"\xff\xfe\x00"), "not UTF-8"),
        (lambda p: None, "no such cell configuration file"),
        (lambda p: p.write_text("[workspace\n"), "is not valid TOML"),
    ],
)
def test_unreadable_cell_files(tmp_path, make, message):
    path = tmp_path / "cell.toml"
    make(path)
    with pytest.raises(InputError, match=message):
        CellConfig.load(path)


def test_the_cli_reports_the_key_and_exits_2(tmp_path):
    cell = tmp_path / "cell.toml"
    cell.write_text("[workspace]\nx_max = inf\n")
    proc = subprocess.run(
        [sys.executable, "-m", "sdi.cli", "plan", "a 3-cube tower", "--cell", str(cell)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert proc.stderr.strip() == "error: workspace.x_max: must be a finite number, got inf"
