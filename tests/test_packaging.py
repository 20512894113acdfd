"""The wheel installs the package `mech` alone, and `import mech` works from it.

`derivations` (the code generator) and `figures` (plot scripts) stay in the source tree:
installed, they would be top-level names in a user's site-packages that collide with any
other package so called. The test builds the wheel from a copy of the sources, reads its
file list, installs it into a fresh virtual environment (a plain venv: no system site
packages to hide a missing dependency) and imports `mech` there in a fresh process.
"""

import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

pytest.importorskip("build")


def _build_wheel(tmp_path):
    src = tmp_path / "src"
    src.mkdir()
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(ROOT / name, src / name)
    shutil.copytree(ROOT / "mech", src / "mech", ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    # what a wheel would pick up if the configuration let it: the collision this test guards
    for name in ("derivations", "figures"):
        shutil.copytree(ROOT / name, src / name, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    dist = tmp_path / "dist"
    # no isolation: the build must not depend on reaching a package index
    subprocess.run([sys.executable, "-m", "build", "--wheel", "--no-isolation", "--skip-dependency-check",
                    "--outdir", str(dist), str(src)], check=True, capture_output=True, text=True)
    wheels = list(dist.glob("mech-*.whl"))
    assert len(wheels) == 1, wheels
    return wheels[0]


def _clean_env():
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
    return env


@pytest.mark.slow  # 15 s on a quiet machine, over a minute on a busy one (build, venv, pip)
def test_wheel_holds_mech_alone_and_imports_in_a_fresh_venv(tmp_path):
    wheel = _build_wheel(tmp_path)
    names = zipfile.ZipFile(wheel).namelist()
    top = {n.split("/", 1)[0] for n in names}
    assert top == {"mech", "mech-0.1.0.dist-info"}, sorted(top)
    assert "mech/__init__.py" in names and "mech/_generated/fourbar_position.py" in names
    assert not any(n.endswith((".pyc", ".md", ".ipynb")) for n in names)

    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)  # no system site packages
    python = venv / "bin" / "python"
    env = _clean_env()
    subprocess.run([str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check", str(wheel)],
                   check=True, env=env, cwd=tmp_path, capture_output=True, text=True)
    script = (
        "import importlib.util, sys\n"
        "import mech\n"
        "from mech.planar import FourBar\n"
        "assert 'site-packages' in mech.__file__, mech.__file__\n"
        "assert importlib.util.find_spec('derivations') is None\n"
        "assert importlib.util.find_spec('figures') is None\n"
        "pose = FourBar(1, 4, 3, 3.5, coupler=(2, 1)).solve([0.0, 1.0])\n"
        "assert pose.valid.all()\n"
        "assert not {'sympy', 'numba', 'scipy'} & set(sys.modules), sorted(sys.modules)\n"
        "print(mech.__file__)\n"
    )
    done = subprocess.run([str(python), "-c", script], env=env, cwd=tmp_path,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert str(venv) in done.stdout
