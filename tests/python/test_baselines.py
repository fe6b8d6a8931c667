"""ffrf.baseline_record and ffrf.baseline_check are `ffrf baseline record|check`: a baseline
recorded from Python passes the command line's check and the command line's passes Python's; a
changed scene value is a regression both name."""

import json

import pytest

import ffrf
from conftest import PAPER, cli


def test_a_python_baseline_passes_the_command_lines_check_and_back(tmp_path):
    recorded = tmp_path / "python.json"
    baseline = ffrf.baseline_record(PAPER, out=recorded, boom="modal", modes=2, duration=20.0)
    assert json.loads(recorded.read_text()) == baseline.summary
    assert baseline.summary["model"]["duration_s"] == 20.0
    assert cli("baseline", "check", PAPER, recorded).returncode == 0
    by_program = tmp_path / "program.json"
    cli("baseline", "record", PAPER, "--boom", "modal", "--modes", 2, "--duration", 20, "--out", by_program)
    check = ffrf.baseline_check(PAPER, by_program)
    assert check.passed and check.failures == 0


def test_a_changed_scene_value_is_a_regression(tmp_path):
    recorded = tmp_path / "base.json"
    ffrf.baseline_record(PAPER, out=recorded, boom="rigid", duration=20.0)
    heavier = ffrf.load_scene(PAPER).with_values({"cargo.mass": "1400 t"})
    check = ffrf.baseline_check(heavier, recorded)
    assert not check.passed and check.failures > 0
    program = cli("baseline", "check", PAPER, recorded, "--set", "cargo.mass=1400 t", check=False)
    assert program.returncode == 4
    with pytest.raises(ffrf.BaselineFileError):
        ffrf.baseline_check(PAPER, tmp_path / "missing.json")
    with pytest.raises(ffrf.SettingError, match="tolerances"):
        ffrf.baseline_check(PAPER, recorded, tolerances={"hook_speed": 1e-3})
