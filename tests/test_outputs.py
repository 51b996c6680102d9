"""`sdi.outputs`: output paths checked first, files written whole or not at all, nothing that
SDI did not write replaced without --force, output folders that never mix two runs."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from sdi.outputs import MANIFEST, OutputError, Outputs, written_by_sdi

SDI = [sys.executable, "-m", "sdi.cli"]


def leftovers(folder: Path) -> list[str]:
    """Temporary files left in `folder`."""
    return sorted(p.name for p in folder.rglob("*.tmp"))


def test_a_new_file_is_written_and_recorded(tmp_path):
    path = tmp_path / "plan.json"
    outputs = Outputs()
    outputs.file(path, "--out")
    assert outputs.commit({path: "{}\n"}) == [path]
    assert path.read_text() == "{}\n" and written_by_sdi(path)
    assert json.loads((tmp_path / MANIFEST).read_text())["files"].keys() == {"plan.json"}
    assert leftovers(tmp_path) == []


def test_sdi_replaces_its_own_file_but_not_an_edited_one(tmp_path):
    path = tmp_path / "plan.json"
    first = Outputs()
    first.file(path, "--out")
    first.commit({path: "one"})
    again = Outputs()
    again.file(path, "--out")  # SDI wrote it: replaced without a word
    again.commit({path: "two"})
    assert path.read_text() == "two"
    path.write_text("edited by hand")
    with pytest.raises(OutputError, match=r"--out: .*SDI did not write it; add --force"):
        Outputs().file(path, "--out")
    assert path.read_text() == "edited by hand"


def test_a_foreign_file_needs_force(tmp_path):
    path = tmp_path / "notes.json"
    path.write_text("mine")
    with pytest.raises(OutputError, match="add --force"):
        Outputs().file(path, "--out")
    forced = Outputs(force=True)
    forced.file(path, "--out")
    forced.commit({path: "sdi"})
    assert path.read_text() == "sdi" and written_by_sdi(path)


@pytest.mark.parametrize(
    ("make", "needle"),
    [
        (lambda t: t, "is a folder; give a file name"),
        (lambda t: t / "missing" / "x.json", "does not exist; create it first"),
        (lambda t: t / "file.txt" / "x.json", "is not a folder"),
        (lambda t: t / MANIFEST, "SDI's manifest"),
    ],
)
def test_unwritable_file_paths_are_refused_up_front(tmp_path, make, needle):
    (tmp_path / "file.txt").write_text("x")
    with pytest.raises(OutputError, match=needle) as info:
        Outputs().file(make(tmp_path), "--python")
    assert info.value.field == "--python"


def test_a_failed_write_leaves_nothing_behind(tmp_path):
    """Every file of a commit is written before the first is renamed into place."""
    sub = tmp_path / "sub"
    sub.mkdir()
    first, second = tmp_path / "a.mod", sub / "prog.py"
    outputs = Outputs()
    outputs.file(first, "--rapid")
    outputs.file(second, "--python")
    sub.rmdir()  # the second path becomes unwritable after the check
    with pytest.raises(OutputError, match=r"--python: cannot write .*prog\.py: no such folder"):
        outputs.commit({first: "MODULE A", second: "print()"})
    assert sorted(p.name for p in tmp_path.iterdir()) == []  # not even a.mod, no .tmp


def test_an_output_folder_never_mixes_two_runs(tmp_path):
    rapid = tmp_path / "rapid"
    two_arms = Outputs()
    two_arms.folder(rapid, "--rapid", patterns=("SDI_*.mod",))
    two_arms.commit({rapid / "SDI_IRB120.mod": "A", rapid / "SDI_IRB1600.mod": "B"})
    (rapid / "README.txt").write_text("the operator's own notes")
    one_arm = Outputs()  # a re-export with one arm
    one_arm.folder(rapid, "--rapid", patterns=("SDI_*.mod",))
    one_arm.commit({rapid / "SDI_IRB120.mod": "A2"})
    names = sorted(p.name for p in rapid.iterdir())
    assert names == [MANIFEST, "README.txt", "SDI_IRB120.mod"]  # the old arm's module is gone
    assert (rapid / "README.txt").read_text() == "the operator's own notes"


def test_a_report_folder_drops_a_stale_plot(tmp_path):
    report = tmp_path / "report"
    passed = Outputs()
    passed.folder(report, "--report", patterns=("report.json", "deviation.png"))
    passed.commit({report / "report.json": '{"v_traj": "pass"}', report / "deviation.png": b"P"})
    failed = Outputs()  # a later run that could not be plotted
    failed.folder(report, "--report", patterns=("report.json", "deviation.png"))
    failed.commit({report / "report.json": '{"v_traj": "fail"}'})
    assert not (report / "deviation.png").exists()
    assert json.loads((report / "report.json").read_text())["v_traj"] == "fail"


def test_a_folder_holding_outputs_sdi_did_not_write_is_refused(tmp_path):
    rapid = tmp_path / "rapid"
    rapid.mkdir()
    (rapid / "SDI_IRB120.mod").write_text("hand-written RAPID")
    with pytest.raises(OutputError, match=r"--rapid: .*SDI_IRB120\.mod, which SDI did not write"):
        Outputs().folder(rapid, "--rapid", patterns=("SDI_*.mod",))
    forced = Outputs(force=True)
    forced.folder(rapid, "--rapid", patterns=("SDI_*.mod",))
    forced.commit({rapid / "SDI_IRB120.mod": "generated"})
    assert (rapid / "SDI_IRB120.mod").read_text() == "generated"


def test_a_file_may_go_into_the_output_folder_the_commit_creates(tmp_path):
    rapid = tmp_path / "robot"
    outputs = Outputs()
    outputs.folder(rapid, "--rapid", patterns=("SDI_*.mod",))
    outputs.file(rapid / "prog.py", "--python")
    outputs.commit({rapid / "SDI_IRB120.mod": "MODULE", rapid / "prog.py": "print()"})
    assert written_by_sdi(rapid / "prog.py") and written_by_sdi(rapid / "SDI_IRB120.mod")


def test_a_folder_path_that_is_a_file_is_refused(tmp_path):
    path = tmp_path / "report"
    path.write_text("x")
    with pytest.raises(OutputError, match="is a file; give a folder"):
        Outputs().folder(path, "--report", patterns=("report.json",))


# -- through the command line -------------------------------------------------------------------


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*SDI, *args], capture_output=True, text=True, timeout=120)


def test_plan_out_refuses_a_foreign_file_and_force_replaces_it(tmp_path):
    out = tmp_path / "plan.json"
    out.write_text("my own notes")
    proc = run("plan", "a 3-cube tower", "--out", str(out))
    assert proc.returncode == 2 and "--force" in proc.stderr and "Traceback" not in proc.stderr
    assert out.read_text() == "my own notes"
    proc = run("plan", "a 3-cube tower", "--out", str(out), "--force")
    assert proc.returncode == 0 and json.loads(out.read_text())["status"] == "success"
    proc = run("plan", "a 2-cube tower", "--out", str(out))  # SDI's own file now
    assert proc.returncode == 0 and len(json.loads(out.read_text())["layout"]["objects"]) == 2
    assert leftovers(tmp_path) == []


def test_bench_out_is_checked_before_the_suite_runs(tmp_path):
    proc = run("bench", "--out", str(tmp_path / "no" / "results.json"))
    assert proc.returncode == 2 and "--out: folder" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_a_re_export_with_fewer_arms_leaves_no_module_of_the_other_arm(tmp_path):
    layout = tmp_path / "tower.json"
    layout.write_text(
        json.dumps(
            {"objects": [{"id": f"c{k}", "position": [0.4, 0.3, 0.025 + 0.05 * k]} for k in (0, 1)]}
        )
    )
    rapid, program = tmp_path / "rapid", tmp_path / "prog.py"
    earlier = Outputs()  # what an earlier two-arm export left behind
    earlier.folder(rapid, "--rapid", patterns=("SDI_*.mod",))
    earlier.file(program, "--python")
    earlier.commit(
        {rapid / "SDI_IRB120.mod": "old", rapid / "SDI_IRB1600.mod": "old", program: "old"}
    )
    db = tmp_path / "runs.sqlite"
    proc = run("run", "--layout", str(layout), "--arms", "irb120", "--approve-all", "--json",
               "--db", str(db))  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    run_id = json.loads(proc.stdout)["run_id"]
    proc = run("export", "--run", run_id, "--db", str(db), "--rapid", str(rapid),
               "--python", str(program))  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    assert sorted(p.name for p in rapid.iterdir()) == [MANIFEST, "SDI_IRB120.mod"]
    assert (rapid / "SDI_IRB120.mod").read_text().startswith("MODULE SDI_IRB120")
    assert program.read_text() != "old" and written_by_sdi(program)
    assert leftovers(tmp_path) == []
