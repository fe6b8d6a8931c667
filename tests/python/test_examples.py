"""The Python examples run headless (matplotlib's Agg backend) with their small settings and write
their charts and tables; the README's "From Python" snippet runs as written."""

import csv
import os
import pathlib
import re
import subprocess
import sys

import pytest

from conftest import SOURCE

EXAMPLES = SOURCE / "examples" / "python"


def run_example(name, out):
    environment = dict(os.environ, MPLBACKEND="Agg")
    result = subprocess.run([sys.executable, str(EXAMPLES / name), "--quick", "--out", str(out)], capture_output=True,
                            text=True, stdin=subprocess.DEVNULL, env=environment, cwd=out.parent, timeout=1800)
    assert result.returncode == 0, result.stderr
    return result


def test_lift_study(tmp_path):
    out = tmp_path / "lift"
    run_example("lift_study.py", out)
    assert (out / "lift_study.png").stat().st_size > 10000
    rows = list(csv.DictReader((out / "lift_study.csv").open()))
    assert len(rows) == 4
    for row in rows:
        assert float(row["error"]) <= 0.01
        assert float(row["work"]) > 0


def test_mode_count(tmp_path):
    out = tmp_path / "modes"
    run_example("mode_count.py", out)
    assert (out / "mode_count.png").stat().st_size > 10000
    rows = list(csv.DictReader((out / "mode_count.csv").open()))
    assert len(rows) == 6
    error = {(int(r["modes"]), r["static_modes"] == "True"): float(r["error"]) for r in rows}
    # Static correction modes capture the static deflection the vibration modes alone miss.
    for k in (1, 2, 3):
        assert error[(k, True)] < error[(k, False)]


def test_readme_snippet(tmp_path):
    readme = (SOURCE / "README.md").read_text(encoding="utf-8")
    section = readme[readme.index("## From Python"):]
    snippet = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    environment = dict(os.environ, MPLBACKEND="Agg")
    result = subprocess.run([sys.executable, "-c", snippet], capture_output=True, text=True, cwd=SOURCE,
                            stdin=subprocess.DEVNULL, env=environment, timeout=1800)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip()
