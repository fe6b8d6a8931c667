"""ffrf.rao and ffrf.modes are `ffrf rao` and `ffrf modes`: the same summaries as the command line's
JSON, the arrays they hold, and the physics: a floating hull follows a long wave (heave RAO → 1 m/m),
and the boom's frequencies approach Euler–Bernoulli's."""

import numpy as np
import pytest

import ffrf
from conftest import ALL_SCENES, PAPER, PINNED, assert_same, cli_json

PERIODS = np.linspace(4.0, 20.0, 33)


def test_rao_equals_the_command_line():
    # --periods a:b:n puts the longest period first; a sequence is taken in its order.
    rao = ffrf.rao(PAPER, periods=PERIODS[::-1], refine_peaks=False)
    program = cli_json("rao", PAPER, "--periods", "4:20:33", "--no-refine-peaks")
    assert_same(rao.summary, program)
    assert [model.label for model in rao.models] == [model["model"] for model in program["models"]]


def test_rao_arrays_and_the_long_wave_limit():
    rao = ffrf.rao(ffrf.load_scene(PAPER), periods=PERIODS, refine_peaks=False)
    rigid = rao.model("rigid")
    np.testing.assert_allclose(rigid.periods, PERIODS, rtol=1e-12)
    heave = rigid.amplitude("hull_heave")
    assert heave.dtype == float and rigid.responses["hull_heave"].dtype == complex
    assert rigid.units["hull_heave"] == "m/m"
    # A long wave lifts the hull with it: the heave RAO tends to 1 m/m as the period grows.
    long_wave = ffrf.rao(PAPER, periods=[200.0, 400.0], boom="rigid", refine_peaks=False).models[0]
    assert long_wave.amplitude("hull_heave")[-1] == pytest.approx(1.0, abs=0.01)
    assert all(mode["period"] > 0 for mode in rigid.natural_modes)
    with pytest.raises(ffrf.SettingError, match=r"periods=-1: out of range \(valid range \(0, 1000\] s\)"):
        ffrf.rao(PAPER, periods=[-1.0])
    with pytest.raises(TypeError, match="not both"):
        ffrf.rao(PAPER, periods=[10.0], frequencies=[0.5])


def test_rao_on_the_pinned_crane_names_one_model():
    rao = ffrf.rao(PINNED, periods=[6.0, 10.0, 14.0], boom="modal", modes=2, refine_peaks=False)
    assert [model.label for model in rao.models] == ["modal k=2+static (N=16)"]
    assert rao.models[0].angular_frequencies.shape == (3,)


@pytest.mark.parametrize("path", ALL_SCENES)
def test_modes_equals_the_command_line_on_every_shipped_scene(path):
    modes = ffrf.modes(path, count=4)
    assert_same(modes.summary, cli_json("modes", path, "--modes", 4))
    assert modes.frequencies_hz.shape == (4,) and modes.shapes.shape[1] == 4


def test_modes_approach_euler_bernoulli():
    coarse = ffrf.modes(PAPER, count=6, elements=8)
    fine = ffrf.modes(PAPER, count=6, elements=32)
    bending = [i for i, kind in enumerate(fine.kinds) if kind == "bending"]
    assert bending
    for i in bending:
        assert fine.relative_errors[i] < coarse.relative_errors[i] + 1e-12
    assert fine.relative_errors[bending[0]] < 1e-6
    # Shapes are M-normalised eigenvectors: as many rows as free DOFs (3 per node, root clamped).
    assert fine.shapes.shape == (3 * 32, 6)
    with pytest.raises(ffrf.SettingError, match=r"count=96: not a mode count of the 96 free DOFs"):
        ffrf.modes(PAPER, count=96, elements=32)
    with pytest.raises(ffrf.SettingError, match="boundary=loose: unknown boundary condition"):
        ffrf.modes(PAPER, boundary="loose")


@pytest.mark.parametrize("name", ["paper_floating_crane", "irregular_sea_crane"])
def test_rao_defaults_are_the_command_lines(name):
    # The default grid (3 to 30 s), refined at the peaks, with the scene's own sea spectrum when it has one.
    path = PAPER.replace("paper_floating_crane", name)
    rao = ffrf.rao(path)
    program = cli_json("rao", path)
    assert_same(rao.summary, program)
    assert (rao.summary.get("sea") is not None) == (name == "irregular_sea_crane")


def test_modes_defaults_are_the_command_lines():
    assert_same(ffrf.modes(PAPER).summary, cli_json("modes", PAPER))
