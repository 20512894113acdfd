"""Every bad command line of the atlas and index CLIs: one line on stderr, status 2, no
traceback (issue 24, item 10).

Run as subprocesses, as a user would; the cases are chosen to fail before any heavy work
(no atlas of more than a few rows is built), so the file stays fast.
"""

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]


def _run(*args, cwd=None):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, env=env, cwd=cwd, timeout=300)


def _one_line_error(result):
    assert result.returncode == 2, (result.returncode, result.stdout, result.stderr)
    assert "Traceback" not in result.stderr, result.stderr
    lines = [ln for ln in result.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1, result.stderr
    return lines[0]


@pytest.mark.parametrize("argv, shown", [
    (["build", "-n", "10", "/dev/null/atlas", "--quiet"], "/dev/null/atlas"),
    # without --quiet the progress bar was drawn before the folder was found unwritable
    (["build", "-n", "10", "/dev/null/atlas"], "`atlas`"),
    (["build", "-n", "10", "--seed", str(10**29), "ATLAS", "--quiet"], "seed"),
    (["build", "-n", "10", "--seed", str(2**63), "ATLAS", "--quiet"], "seed"),
    (["build", "-n", "-3", "ATLAS", "--quiet"], "-3"),
    (["build", "-n", "x", "ATLAS"], "'x'"),
    (["build", "-n", "10", "--min-transmission", "nan", "ATLAS", "--quiet"], "nan"),
    (["build", "-n", "10", "--samples", "3", "ATLAS", "--quiet"], "samples"),
    (["build", "-n", "10", "--dask", "local:x", "ATLAS", "--quiet"], "local:x"),
    (["build", "-n", "10", "--mechanism", "gear", "ATLAS"], "gear"),
    (["query", "NOWHERE", "NOWHERE.csv"], "none"),
    (["query"], "required"),
    ([], "required"),
    (["frobnicate"], "frobnicate"),
])
def test_atlas_cli_bad_command_lines(tmp_path, argv, shown):
    argv = [a.replace("ATLAS", str(tmp_path / "atlas")).replace("NOWHERE", str(tmp_path / "none")) for a in argv]
    line = _one_line_error(_run("-m", "mech.atlas", *argv))
    assert shown in line


def test_atlas_cli_query_of_a_huge_target_prints_finite_errors(tmp_path):
    """Issue 24 item 4: a CSV target scaled by 1e200 printed `error inf (nan %)`."""
    folder = tmp_path / "atlas"
    built = _run("-m", "mech.atlas", "build", str(folder), "-n", "60", "--quiet")
    assert built.returncode == 0, built.stderr
    from mech.atlas import Atlas

    curve = Atlas.from_parquet(folder).curves(7)[0]
    for scale in (1e200, 1e-200):
        path = tmp_path / f"target{scale:g}.csv"
        np.savetxt(path, np.c_[curve.real * scale, curve.imag * scale], delimiter=",", header="x,y")
        result = _run("-W", "error::RuntimeWarning", "-m", "mech.atlas", "query", str(folder), str(path), "-k", "1")
        assert result.returncode == 0, result.stderr
        assert "nan" not in result.stdout and "inf" not in result.stdout, result.stdout
        assert "row 7" in result.stdout


@pytest.mark.parametrize("argv, shown", [
    ([""], "''"),
    (["  "], "'  '"),
    (["2-19x"], "2-19x"),
    (["eq", "x"], "eq x"),
    (["--frobnicate"], "--frobnicate"),
    (["--root", "NOWHERE", "2-19"], "none"),
])
def test_index_cli_bad_command_lines(tmp_path, argv, shown):
    """Issue 24 item 10: `python -m mech.index ""` exited 0 with no output."""
    argv = [a.replace("NOWHERE", str(tmp_path / "none")) for a in argv]
    line = _one_line_error(_run("-m", "mech.index", *argv))
    assert shown in line


def test_index_cli_good_query_still_answers():
    result = _run("-m", "mech.index", "eq", "2-19")
    assert result.returncode == 0 and "2-19" in result.stdout, result.stderr


@pytest.mark.parametrize("argv, shown", [
    (["sheet", "--out", "/dev/null/sheet"], "/dev/null/sheet"),
    (["frobnicate"], "frobnicate"),
    ([], "required"),
])
def test_exercises_cli_bad_command_lines(argv, shown):
    line = _one_line_error(_run("-m", "mech.exercises", *argv))
    assert shown in line
