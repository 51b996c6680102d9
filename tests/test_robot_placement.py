"""Robot placements come from the cell configuration file."""

from __future__ import annotations

import numpy as np

from sdi.model.cell import CellConfig, RobotPlacement
from sdi.robot import default_robots, robots_for
from sdi.tasks import TaskGenerator


def test_default_placements_match_the_documented_cell():
    from_config = robots_for(CellConfig())
    for name, model in default_robots().items():
        np.testing.assert_allclose(from_config[name].T_world_base, model.T_world_base, atol=1e-12)


def test_a_toml_placement_moves_the_robot(tmp_path):
    path = tmp_path / "cell.toml"
    path.write_text(
        '[[robots]]\nname = "left_arm"\nmodel = "irb120"\nbase_xy = [0.0, 0.35]\nbase_yaw_deg = 0\n'
    )
    cell = CellConfig.load(path)
    robots = robots_for(cell)
    assert list(robots) == ["left_arm"]
    np.testing.assert_allclose(robots["left_arm"].T_world_base[:3, 3], (0.0, 0.35, 0.0))
    assert robots["left_arm"].tool.kind == "vacuum"


def test_task_generation_uses_the_configured_robots():
    cell = CellConfig(robots=(RobotPlacement(name="irb120", model="irb120", base_xy=(0.0, 0.30)),))
    generator = TaskGenerator(cell)
    assert list(generator.robots) == ["irb120"]
