"""`RSSR.solve` by the compiled loop (issue 30) against the NumPy path.

The loop calls the same generated functions as the NumPy path on scalars, so the two differ
at most where a libm ``sin``, ``cos``, ``hypot`` or ``atan2`` rounds differently from
NumPy's: the bound checked here is 8 ulp of the field's scale (the largest dimension for
points, pi for angles, the largest value of the field for rates), with the masks equal.
On the machine where this was written the two agreed bit for bit. The NumPy path is checked
against independent oracles in ``test_rssr.py``; here it is the reference.

One loop serves every order and every RSSR; compiling it takes several seconds on a cold
numba cache, so these tests are marked ``slow``.
"""

import numpy as np
import pytest

import mech
from mech._errors import AssemblyError
from mech.spatial._rssr import RSSR

numba = pytest.importorskip("numba")
pytestmark = pytest.mark.slow

ULP = 8 * np.finfo(float).eps
FIELDS = ("phi03", "B", "C", "P", "omega_output", "vB", "vC", "alpha_output", "aB", "aC")
MASKS = ("valid", "assembled")


@pytest.fixture
def backend():
    previous = mech.get_backend()
    yield mech.set_backend
    mech.set_backend(previous)


def _agree(rssr, phi01, order, backend, **rates):
    backend("numpy")
    a = rssr.solve(phi01, order=order, **rates)
    backend("numba")
    b = rssr.solve(phi01, order=order, **rates)
    size = max(abs(x) for x in (rssr.l1, rssr.l2, rssr.l3, rssr.s0, rssr.s3, rssr.h0))
    for name in MASKS:
        if hasattr(a, name) or hasattr(b, name):
            assert np.array_equal(getattr(a, name), getattr(b, name)), name
    for name in FIELDS:
        if not hasattr(a, name):
            assert not hasattr(b, name), name
            continue
        x, y = np.asarray(getattr(a, name)), np.asarray(getattr(b, name))
        assert x.shape == y.shape, name
        assert np.array_equal(np.isnan(x), np.isnan(y)), name
        finite = np.isfinite(x)
        if name == "phi03":
            scale = np.pi
        elif name in ("B", "C", "P"):
            scale = size
        else:
            scale = np.max(np.abs(x[finite]), initial=0.0)
        assert np.all(np.abs(x[finite] - y[finite]) <= ULP * scale), name
    return b


def _random_rssr(rng, unit=1.0):
    l1, l2, l3 = np.exp(rng.uniform(np.log(0.3), np.log(4.0), 3)) * unit
    s0, s3, h0 = rng.uniform(-2.0, 2.0, 3) * unit
    h0 = abs(h0) + 0.1 * unit
    lam = rng.uniform(-3.0, 3.0)
    coupler = tuple(rng.uniform(-1.0, 1.0, 3) * unit) if rng.uniform() < 0.7 else (l2 * 0.4, 0.0, 0.0)
    return RSSR(l1, l2, l3, s0, s3, h0, lam, branch=rng.choice([-1, 1]), coupler=coupler)


@pytest.mark.parametrize("order", [0, 1, 2])
def test_random_linkages_agree(order, backend):
    rng = np.random.default_rng(30)
    partial = 0
    for _ in range(20):
        rssr = _random_rssr(rng)
        if rssr._change is not None:
            continue
        theta = rng.uniform(-10.0, 10.0, 5000)
        got = _agree(rssr, theta, order, backend, omega=rng.uniform(-3, 3, 5000), alpha=0.7)
        partial += bool(got.valid.any() and not got.valid.all())
    assert partial >= 3          # linkages that assemble over part of the turn only


def test_limit_positions_agree(backend):
    rssr = RSSR(2.0, 2.5, 1.5, 0.3, -0.4, 1.5, 0.8)
    ends = rssr.assembly_range().intervals.ravel()
    theta = np.concatenate([ends, np.nextafter(ends, 10.0), np.nextafter(ends, -10.0)])
    got = _agree(rssr, theta, 2, backend, omega=1.0, alpha=0.5)
    assert got.assembled.any() and not got.valid.all()


def test_tiny_unit_and_shapes(backend):
    rng = np.random.default_rng(7)
    rssr = _random_rssr(rng, unit=1e-200)
    theta = rng.uniform(-4.0, 4.0, (50, 60))
    got = _agree(rssr, theta, 2, backend, omega=rng.uniform(-1, 1, 60), alpha=0.3)
    assert got.B.shape == (50, 60, 3) and got.omega_output.shape == (50, 60)
    _agree(rssr, 0.5, 1, backend, omega=2.0)                     # a scalar crank angle


def test_strict_names_the_first_bad_angle(backend):
    rssr = RSSR(2.0, 2.5, 1.5, 0.3, -0.4, 1.5, 0.8)
    backend("numba")
    theta = np.linspace(-np.pi, np.pi, 101)
    with pytest.raises(AssemblyError, match=repr(float(theta[~rssr.solve(theta).valid][0]))):
        rssr.solve(theta, strict=True)


def test_auto_uses_the_loop_from_its_threshold(backend, monkeypatch):
    from mech.spatial import _rssr_compiled

    calls = []
    real = _rssr_compiled.solve_fields
    monkeypatch.setattr(_rssr_compiled, "solve_fields", lambda *args: calls.append(1) or real(*args))
    backend("auto")
    rssr = RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0)
    rssr.solve(np.zeros(100))
    assert not calls
    rssr.solve(np.zeros(5000))
    assert calls


def test_rates_beyond_the_float_range_agree(backend):
    """A crank rate of 1e300 on lengths near 1: the pin velocities overflow, as on NumPy."""
    rssr = RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0)
    theta = np.linspace(-3.0, 3.0, 5000)
    omega = np.where(np.arange(5000) % 7 == 0, 1e300, 1.0)
    got = _agree(rssr, theta, 2, backend, omega=omega, alpha=1e300)
    assert got.assembled.all() and not got.valid.all() and got.valid.any()
