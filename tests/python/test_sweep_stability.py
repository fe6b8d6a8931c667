"""ffrf.sweep and ffrf.stability are `ffrf sweep` and `ffrf stability`: the sweep's rows are the
command line's sweep.csv rows (timings aside) and its summary its JSON; the stability map's summary
is the command line's summary.json, and a temporary report directory is left behind by neither."""

import csv
import io
import json
import os

import pytest

import ffrf
from conftest import PAPER, SPIN_UP, assert_same, cli, volatile

SHORT = 25.0


def rows_of(text):
    return [{key: value for key, value in row.items() if not volatile(key)} for row in csv.DictReader(io.StringIO(text))]


def test_sweep_equals_the_command_line(tmp_path):
    sweep = ffrf.sweep(PAPER, duration=SHORT, jobs=2)
    out = tmp_path / "sweep"
    cli("sweep", PAPER, "--duration", SHORT, "--jobs", 2, "--out", out)
    assert rows_of(sweep.csv) == rows_of((out / "sweep.csv").read_text())
    assert_same(sweep.summary, json.loads((out / "summary.json").read_text()))
    ok = [row for row in sweep.rows if row["status"] == "ok"]
    assert ok and all(row["worst_error"] >= 0.0 for row in ok)
    assert sweep.column("work").shape == (len(sweep.rows),)
    with pytest.raises(ffrf.SettingError, match="grid=huge: unknown sweep grid; choose one of quick, medium, full"):
        ffrf.sweep(PAPER, grid="huge")


def test_stability_equals_the_command_line_and_leaves_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    stability = ffrf.stability(SPIN_UP, quick=True)
    assert os.listdir(tmp_path) == []
    assert_same(stability.summary, json.loads(cli("stability", SPIN_UP, "--quick", "--json").stdout))
    assert set(stability.summary["sections"]) >= {"explicit", "drift", "spin"}
    assert stability.text.startswith("#")
    out = tmp_path / "report"
    ffrf.stability(SPIN_UP, quick=True, out=out)
    assert (out / "report.md").is_file() and (out / "summary.json").is_file()


def test_stability_on_the_reference_crane_names_its_experiments():
    # A crane with a cargo: the explicit step limits, the drift, the dropped cargo's wire and the buckling margin.
    stability = ffrf.stability(PAPER, quick=True)
    assert list(stability.summary["sections"]) == ["explicit", "drift", "wire", "buckling"]
    assert_same(stability.summary, json.loads(cli("stability", PAPER, "--quick", "--json").stdout))
