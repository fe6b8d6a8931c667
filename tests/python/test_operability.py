"""ffrf.operability is `ffrf operability` on threads: a small table equals the command line's
summary.json (timings aside); a KeyboardInterrupt stops it, raises in Python, and leaves no file
behind; its settings are checked as the command line checks them."""

import json
import os
import signal
import threading
import time

import pytest

import ffrf
from conftest import PAPER, assert_same, cli

SMALL = dict(hs=[1.0, 2.0], tp=[8.0], seeds=1, duration=240.0, verify=1, threads=2)


def test_a_small_table_equals_the_command_line(tmp_path):
    table = ffrf.operability(PAPER, **SMALL)
    out = tmp_path / "table"
    cli("operability", PAPER, "--hs", "1:2:2", "--tp", "8", "--seeds", 1, "--duration", 240, "--verify", 1,
        "--threads", 2, "--out", out)
    program = json.loads((out / "summary.json").read_text())
    program.pop("command", None)
    python = dict(table.summary)
    python.pop("command", None)
    assert_same(python, program)
    assert [(cell["hs"], cell["tp"]) for cell in table.cells] == [(1.0, 8.0), (2.0, 8.0)]
    assert all(cell["status"] == "ok" for cell in table.cells)
    hs, tp, utilisation = table.grid("utilisation")
    assert list(hs) == [1.0, 2.0] and list(tp) == [8.0]
    # A higher sea loads the lift more.
    assert utilisation[0, 1] > utilisation[0, 0]


def test_keyboard_interrupt_stops_it_and_leaves_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    timer = threading.Timer(3.0, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        ffrf.operability(PAPER, hs=[1.0, 1.5, 2.0], tp=[6.0, 8.0, 10.0], seeds=2, duration=1800.0, threads=2)
    timer.cancel()
    assert time.monotonic() - started < 60.0  # stopped at the records' next output time, not at their end
    assert os.listdir(tmp_path) == []
    # The next call runs: the stop request was forgotten.
    assert ffrf.run(PAPER, boom="rigid", duration=2.0).time[-1] == pytest.approx(2.0)


def test_settings_are_checked_as_the_command_line_checks_them():
    with pytest.raises(ffrf.SettingError, match=r"Hs = 30 m out of range \(valid range \(0, 20\] m\)"):
        ffrf.operability(PAPER, hs=[30.0], tp=[8.0])
    with pytest.raises(ffrf.SettingError, match=r"headings=beam: not a heading \(following or head\)"):
        ffrf.operability(PAPER, hs=[1.0], tp=[8.0], headings=["beam"])
    with pytest.raises(ffrf.SceneError, match="not a floating crane with a cargo"):
        ffrf.operability(ffrf.load_scene(PAPER.replace("paper_floating_crane", "cantilever")), hs=[1.0], tp=[8.0])
