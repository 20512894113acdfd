"""``import mech`` must stay light: NumPy only, no SymPy, SciPy, Matplotlib, pyarrow or Dask.

Each import runs in a fresh interpreter (``sys.executable``), because the test process
itself has long since imported the heavy libraries through pytest plugins and other tests.
"""

import importlib.util
import subprocess
import sys

import pytest

HEAVY = ("sympy", "scipy", "matplotlib", "pyarrow", "dask", "distributed", "tqdm")


def _heavy_modules_after(statements):
    """Run ``statements`` in a new interpreter; return the heavy top-level modules it loaded."""
    probe = "\n".join(
        [
            *statements,
            "import sys",
            f"heavy = {HEAVY!r}",
            "loaded = sorted({name.split('.')[0] for name in sys.modules} & set(heavy))",
            "print(','.join(loaded))",
        ]
    )
    done = subprocess.run(
        [sys.executable, "-c", probe], capture_output=True, text=True, timeout=120, check=False
    )
    assert done.returncode == 0, f"the import failed:\n{done.stderr}"
    out = done.stdout.strip().splitlines()
    return out[-1].split(",") if out and out[-1] else []


def test_import_mech_light():
    assert _heavy_modules_after(["import mech"]) == []


def test_import_mech_planar_light():
    assert _heavy_modules_after(["import mech.planar"]) == []


def test_import_mech_planar_attribute_access_light():
    """Reaching the subpackage through ``mech.planar`` (lazy attribute) stays light too."""
    statements = ["import mech", "mech.planar.FourBar, mech.planar.SliderCrank, mech.planar.grashof"]
    assert _heavy_modules_after(statements) == []


def test_import_mech_exercises_light():
    if importlib.util.find_spec("mech.exercises") is None:
        pytest.skip("mech.exercises does not exist yet")
    assert _heavy_modules_after(["import mech.exercises"]) == []


def test_heavy_modules_after_detects_heavy_import():
    """The probe itself can fail: importing SymPy directly is reported."""
    pytest.importorskip("sympy")
    assert _heavy_modules_after(["import sympy"]) == ["sympy"]


def test_import_mech_spatial_light():
    assert _heavy_modules_after(["import mech.spatial"]) == []


def test_import_mech_spherical_light():
    assert _heavy_modules_after(["import mech.spherical"]) == []


def test_import_mech_planar_synthesis_light():
    """The synthesis subpackage loads SciPy and tqdm only inside the searches that use them."""
    statements = ["import mech.planar.synthesis", "import mech.exercises.chapter2"]
    assert _heavy_modules_after(statements) == []


def test_import_mech_atlas_light():
    """The atlas loads pyarrow only to save or load, tqdm only for a progress bar."""
    assert _heavy_modules_after(["import mech.atlas"]) == []
    statements = ["import mech.atlas as at", "at.query(at.build_atlas(50), [0, 1, 1 + 1j, 1j])"]
    assert _heavy_modules_after(statements) == []
