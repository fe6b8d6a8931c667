"""Scenes as values: every shipped scene loads; with_values gives the scene the command line's
--set gives (checked against `ffrf check --set`) and a new value, leaving the old one as it was; an
invalid value raises SceneError naming the key, the value, the valid range and where it came from,
with the command line's message."""

import math

import pytest

import ffrf
from conftest import ALL_SCENES, CANTILEVER, PAPER, cli


@pytest.mark.parametrize("path", ALL_SCENES)
def test_every_shipped_scene_loads_as_the_program_checks_it(path):
    scene = ffrf.load_scene(path)
    assert scene.path == path
    assert scene.kind in ("crane", "hub", "beam")
    assert scene.values == {}
    assert cli("check", path).returncode == 0


def test_with_values_makes_a_new_scene_and_keeps_the_old():
    scene = ffrf.load_scene(PAPER)
    lift = scene.with_values({"boom.angle": "55 deg", "cargo.mass": "2400 t"})
    assert lift is not scene
    assert scene.values == {}
    assert lift.values == {"boom.angle": "55 deg", "cargo.mass": "2400 t"}
    # A later value of a key replaces the earlier; the others stay.
    again = lift.with_values({"boom.angle": "50 deg"}, **{"boom.elements": 8})
    assert again.values == {"boom.angle": "50 deg", "cargo.mass": "2400 t", "boom.elements": "8"}
    assert again.facts["elements"] == 8
    assert lift.facts["elements"] == 16
    # Recorded in the run's provenance, in order.
    assert lift.facts["overrides"] == ["boom.angle=55 deg", "cargo.mass=2400 t"]


def test_python_values_are_written_as_on_the_command_line():
    scene = ffrf.load_scene(CANTILEVER)
    changed = scene.with_values({"boom.elements": 4, "simulation.duration": 12.5, "boom.boundary": "pinned-pinned"})
    assert changed.values == {"boom.elements": "4", "simulation.duration": "12.5", "boom.boundary": "pinned-pinned"}
    assert changed.facts["elements"] == 4
    assert changed.facts["duration"] == 12.5
    with pytest.raises(TypeError, match="boom.elements"):
        scene.with_values({"boom.elements": object()})


def test_an_invalid_value_names_key_value_range_and_origin():
    scene = ffrf.load_scene(PAPER)
    with pytest.raises(ffrf.SceneError) as raised:
        scene.with_values({"boom.angle": "155 deg"})
    error = raised.value
    assert isinstance(error, ValueError)
    [problem] = error.problems
    assert problem["key"] == "boom.angle"
    assert problem["value"] == "155 deg"
    assert problem["origin"] == "with_values"
    assert "(valid range (0, 90) deg)" in problem["message"]
    assert problem["text"] == f"{PAPER}: boom.angle = 155 deg (with_values): {problem['message']}"
    # The command line's message for the same value differs only in its origin.
    printed = cli("check", PAPER, "--set", "boom.angle=155 deg", check=False)
    assert printed.returncode == 2
    assert problem["text"].replace("(with_values)", "(--set)") in printed.stderr


def test_unknown_keys_and_unit_slips_are_named_as_the_program_names_them():
    scene = ffrf.load_scene(PAPER)
    with pytest.raises(ffrf.SceneError) as raised:
        scene.with_values({"boom.angel": "55 deg", "cargo.mass": "2400 m"})
    keys = {problem["key"]: problem for problem in raised.value.problems}
    assert "did you mean boom.angle?" in keys["boom.angel"]["message"]
    assert "valid range [0.001, 100000] t" in keys["cargo.mass"]["message"]
    printed = cli("check", PAPER, "--set", "boom.angel=55 deg", "--set", "cargo.mass=2400 m", check=False)
    for problem in raised.value.problems:
        assert problem["text"].replace("(with_values)", "(--set)") in printed.stderr


def test_the_keys_across_each_other_are_checked_again():
    # A pinned heel needs the luffing wires the reference crane does not have.
    with pytest.raises(ffrf.SceneError, match=r"boom.heel = pinned \(with_values\).*\[luffing\]"):
        ffrf.load_scene(PAPER).with_values({"boom.heel": "pinned"})


def test_a_missing_file_is_a_scene_error():
    with pytest.raises(ffrf.SceneError, match="cannot open the scene file"):
        ffrf.load_scene("/nonexistent/scene.toml")


def test_scene_from_text_equals_the_file():
    text = open(PAPER, encoding="utf-8").read()
    scene = ffrf.scene_from_text(text, path=PAPER, values={"wave.height": 1.5})
    assert scene.values == {"wave.height": "1.5"}
    assert math.isclose(scene.facts["duration"], 120.0)
