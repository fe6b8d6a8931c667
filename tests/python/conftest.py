"""What the Python module's tests share: the shipped scenes, the command-line program, and a
comparison of the binding's results with the program's output for the same settings.

ctest runs each test file with the build's python folder on PYTHONPATH, FFRF_SOURCE_DIR (the
repository) and FFRF_PROGRAM (the built ``ffrf``) in the environment (tests/python/CMakeLists.txt).
"""

import json
import math
import re
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("FFRF_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
PROGRAM = os.environ.get("FFRF_PROGRAM", str(SOURCE / "build" / "app" / "ffrf"))
CASES = SOURCE / "cases"

PAPER = str(CASES / "paper_floating_crane.toml")
PINNED = str(CASES / "pinned_luffing_crane.toml")
A_FRAME = str(CASES / "a_frame_crane.toml")
DROPPED = str(CASES / "dropped_load.toml")
SPIN_UP = str(CASES / "spin_up_beam.toml")
CANTILEVER = str(CASES / "cantilever.toml")
# Every shipped scene, and those that make a time-domain system (a floating crane or a hub).
ALL_SCENES = sorted(str(path) for path in CASES.glob("*.toml"))


def cli(*arguments, check=True, cwd=None):
    """Runs the command-line program (no terminal on stdin); returns the CompletedProcess."""
    result = subprocess.run([PROGRAM, *map(str, arguments)], capture_output=True, text=True, stdin=subprocess.DEVNULL,
                            cwd=cwd, timeout=1800)
    if check and result.returncode != 0:
        raise AssertionError(f"ffrf {' '.join(map(str, arguments))} exited {result.returncode}:\n{result.stderr}")
    return result


def cli_json(*arguments):
    return json.loads(cli(*arguments, "--json").stdout)


# Keys whose values depend on the machine's load or the moment (timings, dates, speed-ups measured
# by wall time, the Pareto front of error against wall time) or on where the outputs went: not compared.
VOLATILE = ("wall", "date", "real_time", "seconds", "elapsed", "timing", "pareto", "charts", "timeseries", "journal",
            "eta")


def volatile(key):
    return any(part in key.lower() for part in VOLATILE)


# Measured wall-time ratios inside sentences ("wall time 3.1× less").
WALL_TIME = re.compile(r"wall time [0-9.e+-]+×")


def assert_same(python, program, path="summary"):
    """The binding's JSON equals the program's, number for number (to the last printed digit: both
    are printed by the same code), but for the volatile keys."""
    if isinstance(program, dict):
        assert isinstance(python, dict), path
        keys = {key for key in program if not volatile(key)}
        assert keys == {key for key in python if not volatile(key)}, f"{path}: keys differ"
        for key in keys:
            assert_same(python[key], program[key], f"{path}.{key}")
    elif isinstance(program, list):
        assert isinstance(python, list) and len(python) == len(program), f"{path}: lengths differ"
        for i, (a, b) in enumerate(zip(python, program)):
            assert_same(a, b, f"{path}[{i}]")
    elif isinstance(program, float) and math.isnan(program):
        assert isinstance(python, float) and math.isnan(python), path
    elif isinstance(program, str):
        assert WALL_TIME.sub("wall time ×", python) == WALL_TIME.sub("wall time ×", program), f"{path}: {python!r} != {program!r}"
    else:
        assert python == program, f"{path}: {python!r} != {program!r}"


@pytest.fixture
def paper():
    import ffrf
    return ffrf.load_scene(PAPER)
