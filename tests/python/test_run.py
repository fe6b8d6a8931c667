"""ffrf.run is `ffrf run`: the same scene, values and settings give the command line's summary.json
number for number and its timeseries.csv to the last printed digit; every shipped time-domain scene
runs; bad settings raise SettingError with the command line's message, naming the keyword; a
failed solver raises SolverFailure naming the failure and what to adjust."""

import csv
import json

import numpy as np
import pytest

import ffrf
from conftest import A_FRAME, ALL_SCENES, PAPER, PINNED, assert_same, cli

LIFT = {"boom.angle": "55 deg", "cargo.mass": "2400 t"}


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    return rows[0], rows[1:]


def test_run_equals_the_command_line(tmp_path):
    scene = ffrf.load_scene(PAPER).with_values(LIFT)
    run = ffrf.run(scene, boom="modal", modes=2, static_modes=True, duration=60.0)
    out = tmp_path / "run"
    cli("run", PAPER, "--set", "boom.angle=55 deg", "--set", "cargo.mass=2400 t", "--boom", "modal", "--modes", 2,
        "--static-modes", "--duration", 60, "--out", out)
    summary = json.loads((out / "summary.json").read_text())
    assert_same(run.summary, summary)
    assert summary["provenance"]["scene_overrides"] == ["boom.angle=55 deg", "cargo.mass=2400 t"]

    header, rows = read_csv(out / "timeseries.csv")
    assert header[0] == "time_s"
    # Every column of the CSV is an output, named by the output-channel table, and nothing else.
    assert header[1:] == [run.columns[name] for name in run.outputs]
    assert len(rows) == len(run.time) == 1201
    for i, row in enumerate(rows):
        assert row[0] == f"{run.time[i]:.10g}"
        for value, name in zip(row[1:], run.outputs):
            assert value == f"{run.outputs[name][i]:.10g}", (name, i)


def test_outputs_are_numpy_arrays_in_the_csv_units():
    run = ffrf.run(ffrf.load_scene(PAPER), boom="rigid", duration=20.0)
    assert isinstance(run.time, np.ndarray) and run.time[0] == 0.0 and run.time[-1] == pytest.approx(20.0)
    assert run.units["crane_pitch"] == "deg"
    assert run.columns["wire_tension"] == "wire_tension_N"
    # Motions are displacements from the static equilibrium: zero at t = 0, which starts from it.
    assert run.outputs["cargo_heave"][0] == pytest.approx(0.0, abs=1e-9)
    # The wire carries the cargo's weight (and buoyancy-free) at rest: 1 300 t × g.
    assert run.outputs["wire_tension"][0] == pytest.approx(1.3e6 * 9.81, rel=1e-6)
    assert run.statics is not None and run.solver["steps"] > 0
    assert run.model == "rigid"


@pytest.mark.parametrize("path", [p for p in ALL_SCENES if "cantilever" not in p])
def test_every_shipped_time_domain_scene_runs(path):
    run = ffrf.run(path, duration=2.0)
    assert len(run.time) >= 2 and np.all(np.isfinite(run.time))
    assert set(run.outputs) == set(run.columns)
    assert run.summary["provenance"]["scene"] == path


def test_bad_settings_raise_setting_error_with_the_command_lines_message():
    scene = ffrf.load_scene(PAPER)
    # The study's words, as the command line prints them after its option's name.
    for keywords, arguments in (({"boom": "beam"}, ["--boom", "beam"]),
                                ({"formulation": "index2", "solver": "explicit-rk"},
                                 ["--formulation", "index2", "--solver", "explicit-rk"]),
                                ({"boom": "modal", "modes": 48}, ["--boom", "modal", "--modes", "48"]),
                                ({"duration": 0.01}, ["--duration", "0.01"])):
        with pytest.raises(ffrf.SettingError) as python:
            ffrf.run(scene, **keywords)
        printed = cli("run", PAPER, *arguments, check=False)
        assert printed.returncode == 2
        assert python.value.problem in printed.stderr, (python.value, printed.stderr)
        assert str(python.value).startswith(f"{python.value.keyword}={python.value.value}: ")
    with pytest.raises(ffrf.SettingError, match=r"rtol=0: not a valid tolerance \(valid range \[1e-12, 0.1\]\)"):
        ffrf.run(scene, rtol=0.0)
    with pytest.raises(ffrf.SettingError, match=r"max_steps=0: not a step limit \(valid range \[1, 1000000000\]\)"):
        ffrf.run(scene, max_steps=0)
    with pytest.raises(TypeError, match="modes: expected a whole number"):
        ffrf.run(scene, boom="modal", modes=2.5)


def test_a_failed_solver_raises_solver_failure():
    # An explicit Runge-Kutta step far beyond the boom's stability limit diverges (docs/stability.md).
    with pytest.raises(ffrf.SolverFailure) as raised:
        ffrf.run(ffrf.load_scene(PAPER), boom="nodal", elements=16, integrator="arkode", step=0.05, duration=10.0)
    failure = raised.value
    assert failure.kind
    assert failure.time >= 0.0
    assert "step" in failure.adjust or "rtol" in failure.adjust
    assert str(failure).startswith(f"solver failure ({failure.kind}):")


def test_the_gil_is_released_while_a_study_runs():
    # Another Python thread keeps running while the crane is integrated.
    import threading
    import time
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    started = time.monotonic()
    ffrf.run(PAPER, boom="nodal", elements=32, duration=120.0)
    finished = time.monotonic()
    done.set()
    ticker.join()
    during = [t for t in ticks if started < t < finished]
    # Holding the GIL through the call would leave the ticker no tick at all until it returned.
    assert finished - started > 0.2
    assert len(during) >= 20


def test_stress_recovery_is_a_keyword_of_run(tmp_path):
    # The pinned crane's boom stress by mode displacement and by mode acceleration: the run's own
    # channel is the recovery asked for, and the command line gives the same numbers for the same choice.
    pinned = PINNED
    by = {}
    for recovery, option in (("displacement", "displacement"), ("acceleration", "acceleration")):
        run = ffrf.run(pinned, boom="modal", modes=2, static_modes=False, stress_recovery=recovery, duration=5.0)
        by[recovery] = run.outputs["boom_peak_stress"]
        assert run.units["boom_peak_stress"] == "MPa"
        assert np.all(by[recovery] > 0.0)
        printed = cli("run", pinned, "--boom", "modal", "--modes", 2, "--no-static-modes", "--stress-recovery", option,
                      "--duration", 5, "--json")
        assert_same(run.summary, json.loads(printed.stdout))
    # The envelope along the boom is boom_stress.csv's, in MPa; its largest stress is the run's peak.
    out = tmp_path / "stress"
    cli("run", PINNED, "--boom", "modal", "--modes", 2, "--no-static-modes", "--stress-recovery", "acceleration",
        "--duration", 5, "--out", out)
    header, rows = read_csv(out / "boom_stress.csv")
    envelope = run.boom_stress
    assert len(rows) == len(envelope["position"])
    column = header.index("stress_max_MPa")
    for row, value in zip(rows, envelope["stress_max"]):
        assert float(row[column]) == pytest.approx(value, rel=1e-8)
    # The sections are the nodes; the run's peak is sought between them too, so it is at least theirs.
    extreme = max(np.max(envelope["stress_max"]), -np.min(envelope["stress_min"]))
    assert extreme <= np.max(by["acceleration"]) * (1 + 1e-9)
    assert extreme >= 0.95 * np.max(by["acceleration"])
    # Two modes alone leave the wire's and the heel's static response out: the recoveries differ.
    assert np.max(np.abs(by["displacement"] - by["acceleration"])) > 1e-3 * np.max(by["acceleration"])
    with pytest.raises(ffrf.SettingError, match="stress_recovery=velocity"):
        ffrf.run(pinned, boom="modal", stress_recovery="velocity")


def test_the_mode_set_is_a_keyword_of_run():
    # Every mode set of the pinned crane, named as on the command line, gives the command line's
    # numbers; with static modes the two sets of the heel's tangent frame agree to the reference's
    # resolution (docs/validation.md), the chord frame's set differs.
    peak = {}
    for mode_set in ("clamped-free", "free-free", "pinned-pinned"):
        run = ffrf.run(PINNED, boom="modal", modes=2, mode_set=mode_set, duration=5.0)
        assert mode_set == "clamped-free" or mode_set in run.summary["model"]
        printed = cli("run", PINNED, "--boom", "modal", "--modes", 2, "--mode-set", mode_set, "--duration", 5, "--json")
        assert_same(run.summary, json.loads(printed.stdout))
        peak[mode_set] = run.outputs["boom_peak_stress"]
    assert np.max(np.abs(peak["free-free"] - peak["clamped-free"])) < 1e-3 * np.max(peak["clamped-free"])
    with pytest.raises(ffrf.SettingError, match="mode_set"):
        ffrf.run(PINNED, boom="modal", mode_set="hinged", duration=1.0)


def test_the_a_frame_on_its_pin_reports_its_backstays(tmp_path):
    # The A-frame's rotation is a motion about the static equilibrium (zero at the start from it); the
    # backstays' tension at rest is the static equilibrium's, as the command line reports it, and
    # holds the A-frame against the luffing wires' pull (both tens of MN).
    run = ffrf.run(A_FRAME, duration=2.0)
    assert run.outputs["a_frame_rotation"][0] == pytest.approx(0.0, abs=1e-12)
    out = tmp_path / "run"
    cli("run", A_FRAME, "--duration", 2, "--out", out)
    with open(out / "summary.json") as f:
        statics = json.load(f)["static_equilibrium"]
    assert run.outputs["backstay_tension"][0] == pytest.approx(statics["backstay_tension_N"], rel=1e-9)
    assert 1e7 < run.outputs["backstay_tension"][0] < 1e8
    assert 1e7 < run.outputs["luffing_tension"][0] < 1e8
