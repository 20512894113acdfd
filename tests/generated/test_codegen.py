"""The generator's backends: overflow-safe printing, per-function equations, files written
only when their content changes, and the JavaScript module's freshness."""

import importlib.util
import math

import numpy as np
import pytest
import sympy as sm

from derivations import _codegen, _node
from derivations._printers import hypot, overflow_safe


@pytest.fixture
def tmp_generated(tmp_path, monkeypatch):
    monkeypatch.setattr(_codegen, "GENERATED_DIR", tmp_path)
    monkeypatch.setattr(_codegen, "JS_DIR", tmp_path)
    monkeypatch.delenv("MECH_CODEGEN", raising=False)
    return tmp_path


def _load(path):
    spec = importlib.util.spec_from_file_location(f"_probe_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_overflow_safe_finds_sums_of_squares():
    x, y, z = sm.symbols("x y z", real=True)
    assert overflow_safe(sm.sqrt(x**2 + y**2)) == hypot(x, y)
    assert overflow_safe(sm.sqrt(x**2 + 4 * y**2)) == hypot(x, 2 * y)
    assert overflow_safe(1 / sm.sqrt(x**2 + y**2 + z**2)) == 1 / hypot(hypot(x, y), z)
    # not a sum of squares: left alone
    for e in (sm.sqrt(x**2 - y**2), sm.sqrt(x**2 + y), sm.sqrt(2 * x**2 + y**2), sm.sqrt(x**2 + y**2 + sm.I)):
        assert not overflow_safe(e).has(hypot)


def test_hypot_keeps_huge_inputs_finite(tmp_generated):
    """sqrt(x**2 + y**2) at x = 1e300 overflows as written; every backend prints hypot, so
    the value is right (checked against the exact 5e300 of a 3-4-5 triangle)."""
    x, y = sm.symbols("x y", real=True)
    f = _codegen.Function("norm", "Length of (x, y).", ((x, "x"), (y, "y")),
                          (("r", sm.sqrt(x**2 + y**2), "length"),), {x: (-1, 1), y: (-1, 1)}, vector=(y,))
    _codegen.write("norm", "derivations/norm.md", "(0-0)", [f])
    module = _load(tmp_generated / "norm.py")
    assert module.norm(3e300, 4e300) == 5e300
    out = np.empty(1)
    module.norm_into(3e300, np.array([4e300]), (out,), np.empty((module.WORK_ROWS["norm"], 1)))
    assert out[0] == 5e300
    assert "np.hypot" in (tmp_generated / "norm.py").read_text()
    assert "math.hypot" in (tmp_generated / "norm_numba.py").read_text()
    if _node.node() is not None:
        got = _node.evaluate([(tmp_generated / "norm.js", "norm", [np.array([3e300]), np.array([4e300])], 1)])
        assert got[0][0, 0] == 5e300


def test_docstrings_cite_their_own_equations(tmp_generated):
    x = sm.symbols("x", real=True)
    own = _codegen.Function("own", "Own.", ((x, "x"),), (("y", x + 1, "y"),), equations="(3-7)")
    shared = _codegen.Function("shared", "Shared.", ((x, "x"),), (("y", x - 1, "y"),))
    _codegen.write("eqs", "derivations/eqs.md", "(3-1) to (3-9)", [own, shared])
    module = _load(tmp_generated / "eqs.py")
    assert "equations (3-7)." in module.own.__doc__
    assert "equations (3-1) to (3-9)." in module.shared.__doc__
    js = (tmp_generated / "eqs.js").read_text()
    assert "equations (3-7)." in js and "equations (3-1) to (3-9)." in js


def test_unchanged_kernels_are_not_rewritten(tmp_generated):
    """Changing a function without kernels rewrites the NumPy and JavaScript modules but not
    the numba module, whose hash covers the functions with kernels only."""
    x, a = sm.symbols("x a", real=True)
    kernel = _codegen.Function("k", "Kernel.", ((a, "a"), (x, "x")), (("y", a * sm.sin(x), "y"),),
                               {a: (1, 2)}, vector=(x,))
    plain = _codegen.Function("p", "Plain.", ((x, "x"),), (("y", x**3, "y"),))
    _codegen.write("mixed", "derivations/mixed.md", "(0-0)", [kernel, plain])
    numba_path = tmp_generated / "mixed_numba.py"
    before = numba_path.stat().st_mtime_ns, numba_path.read_text()
    numpy_before = (tmp_generated / "mixed.py").read_text()
    changed = _codegen.Function("p", "Plain.", ((x, "x"),), (("y", x**3 + 1, "y"),))
    _codegen.write("mixed", "derivations/mixed.md", "(0-0)", [kernel, changed])
    assert (numba_path.stat().st_mtime_ns, numba_path.read_text()) == before
    assert (tmp_generated / "mixed.py").read_text() != numpy_before
    # writing the same inputs again touches nothing
    stamps = {p.name: p.stat().st_mtime_ns for p in tmp_generated.iterdir()}
    _codegen.write("mixed", "derivations/mixed.md", "(0-0)", [kernel, changed])
    assert {p.name: p.stat().st_mtime_ns for p in tmp_generated.iterdir()} == stamps


def test_stale_or_missing_javascript_is_detected(tmp_generated):
    x = sm.symbols("x", real=True)
    f = _codegen.Function("sq", "Square.", ((x, "x"),), (("y", x**2, "y"),))
    _codegen.write("sq", "derivations/sq.md", "(0-0)", [f])
    js = tmp_generated / "sq.js"
    good = js.read_text()
    js.write_text(good.replace('INPUT_HASH = "sha256:', 'INPUT_HASH = "sha256:0'))
    with pytest.raises(AssertionError, match="sq.js is stale"):
        _codegen.check_fresh("sq", "derivations/sq.md", "(0-0)", [f])
    js.unlink()
    with pytest.raises(AssertionError, match="sq.js is missing"):
        _codegen.check_fresh("sq", "derivations/sq.md", "(0-0)", [f])
    if _node.node() is not None:
        # a module whose hash matches but whose numbers are wrong is caught under Node
        js.write_text(good.replace("return (x*x);", "return (x*x) + 1e-6;"))
        with pytest.raises(AssertionError, match="sq.js:sq.y disagrees with mpmath"):
            _codegen.check_fresh("sq", "derivations/sq.md", "(0-0)", [f])


def test_javascript_signatures_and_complex_outputs(tmp_generated):
    if _node.node() is None:
        pytest.skip("node is not installed")
    x, a = sm.symbols("x a", real=True)
    f = _codegen.Function("rot", "a e^{ix}.", ((a, "a"), (x, "x")), (("z", a * sm.exp(sm.I * x), "point"),),
                          {a: (1, 2), x: (-1, 1)})
    _codegen.write("rot", "derivations/rot.md", "(0-0)", [f])
    got = _node.evaluate([(tmp_generated / "rot.js", "rot", [np.array([2.0]), np.array([0.5])], 2)])[0]
    assert got[0, 0] == pytest.approx(2 * math.cos(0.5), rel=1e-15)
    assert got[1, 0] == pytest.approx(2 * math.sin(0.5), rel=1e-15)
    assert '"outputs":["z_re","z_im"]' in (tmp_generated / "rot.js").read_text()
