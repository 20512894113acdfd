"""The NumPy and numba backends evaluate the same generated expressions (issue 16).

The code generator emits each solver's common-subexpression-eliminated expressions twice:
NumPy kernels writing into reused buffers, and numba fused loops. Here the two agree to a
few units in the last place on the four-bar (plain and change-point), and the spherical
four-bar, at order 2; ``import mech`` and a small solve do not import numba; the switch
takes ``"auto"``, ``"numpy"``, ``"numba"`` and the environment variable ``MECH_BACKEND``.
Accuracy against independent references is checked by the solvers' own test files, run
with ``MECH_BACKEND=numpy`` and ``MECH_BACKEND=numba``.
"""

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import mech
from mech.planar import FourBar
from mech.spherical import SphericalFourBar

ROOT = Path(__file__).resolve().parents[1]
FIELDS_PLANAR = ("B", "C", "P", "vB", "vC", "vP", "aB", "aC", "aP", "omega_coupler", "omega_output",
                 "alpha_coupler", "alpha_output")
FIELDS_SPHERICAL = ("B", "C", "P", "psi", "vB", "vC", "vP", "aB", "aC", "aP", "omega_output", "alpha_output")


@pytest.fixture
def backend():
    previous = mech.get_backend()
    yield mech.set_backend
    mech.set_backend(previous)


def _both(backend, make, theta, fields):
    got = {}
    for name in ("numpy", "numba"):
        backend(name)
        pose = make().solve(theta, order=2, omega=1.3, alpha=-0.4)
        got[name] = (pose.valid.copy(), {f: np.asarray(getattr(pose, f)) for f in fields})
    return got


def _assert_ulps(got, ulps):
    (valid_a, a), (valid_b, b) = got["numpy"], got["numba"]
    np.testing.assert_array_equal(valid_a, valid_b)
    for name in a:
        x, y = a[name][valid_a], b[name][valid_a]
        scale = np.max(np.abs(x))
        worst = np.max(np.abs(x - y)) / np.spacing(scale)
        assert worst <= ulps, f"{name}: the backends differ by {worst:.1f} ulp of {scale:.3g}"


@pytest.mark.parametrize("lengths, coupler", [
    ((1.0, 4.0, 3.0, 3.5), (2.0, 1.0)),           # crank-rocker, example of the benchmarks
    ((10.0, 40.0, 30.0, 35.0), (20.0, 10.0)),     # example 2-1 with a coupler point
    ((2.0, 3.0, 2.5, 3.0), (1.0, -0.5)),          # double rocker: dead points, NaN outside
    ((1.0, 2.0, 1.0, 2.0), (0.5, 0.5)),           # parallelogram: change points (signed kernel)
])
def test_fourbar_backends_agree(backend, lengths, coupler):
    pytest.importorskip("numba")
    theta = np.linspace(-7.0, 7.0, 5001)
    got = _both(backend, lambda: FourBar(*lengths, coupler=coupler), theta, FIELDS_PLANAR)
    _assert_ulps(got, 64)


def test_spherical_backends_agree(backend):
    pytest.importorskip("numba")
    theta = np.linspace(-3.1, 3.1, 4001)
    got = _both(backend, lambda: SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.5)), theta,
                FIELDS_SPHERICAL)
    _assert_ulps(got, 64)


def test_backends_agree_in_the_last_places_on_positions(backend):
    """Positions of a crank-rocker away from dead points: within 4 ulp."""
    pytest.importorskip("numba")
    theta = np.linspace(0.0, 2 * np.pi, 10007)
    got = {}
    for name in ("numpy", "numba"):
        backend(name)
        pose = FourBar(1.0, 4.0, 3.0, 3.5, coupler=(2.0, 1.0)).solve(theta)
        got[name] = (pose.valid.copy(), {f: getattr(pose, f) for f in ("B", "C", "P")})
    _assert_ulps(got, 4)


@pytest.mark.parametrize("lengths, coupler", [
    ((1.0, 4.0, 3.0, 3.5), (2.0, 1.0)),           # crank-rocker (exponent 3)
    ((0.2, 0.9, 0.7, 0.8), (0.25, 0.1)),          # exponent 0: scale 1
    ((2.0, 3.0, 2.5, 3.0), (1.0, -0.5)),          # double rocker: NaN where it cannot assemble
    ((1.0, 2.0, 1.0, 2.0), (0.5, 0.5)),           # parallelogram: the signed kernel
    ((3e250, 1.2e251, 9e250, 1.05e251), (6e250, 3e250)),  # points near 1e251, exponent 835
])
def test_fused_position_kernel_gives_the_same_bits(backend, lengths, coupler):
    """Order 0 on numba runs the fused kernel (scaling, mask and finiteness check in its
    loop); order 2 runs the plain kernel and scales afterwards: the same bits."""
    pytest.importorskip("numba")
    backend("numba")
    theta = np.linspace(-7.0, 7.0, 40001).reshape(1, -1)    # several blocks, a 2-D shape
    linkage = FourBar(*lengths, coupler=coupler)
    fused, plain = linkage.solve(theta), linkage.solve(theta, order=2)
    np.testing.assert_array_equal(fused.valid, plain.assembled)
    assert fused.valid.shape == theta.shape
    for name in ("B", "C", "P", "phi", "psi"):
        a, b = getattr(fused, name), getattr(plain, name)
        np.testing.assert_array_equal(a[fused.valid], b[fused.valid])
    assert np.isnan(fused.C[~fused.valid]).all()
    if not fused.valid.all():
        with pytest.raises(mech.AssemblyError, match="theta"):
            linkage.solve(theta, strict=True)
    # the fused path checks theta through its outputs: NaN and infinities still raise
    for bad in (np.nan, np.inf, -np.inf):
        angles = theta.copy()
        angles[0, 30000] = bad
        with pytest.raises(ValueError, match=r"Expected finite `theta`, got (nan|inf|-inf)"):
            linkage.solve(angles)



def test_fused_flag_is_every_output_finite():
    """The fused kernels' flag sums only C and P (the derivation shows B and S follow): on
    random unit four-bars, coupler points up to 1e300, angles with NaN, infinities and
    near-zero |BD|, and scales up to 2**1000, the flag is True exactly when all seven
    outputs are finite at every point (checked here with np.isfinite on each output),
    unless every output is finite and their sum overflows (then False, as documented)."""
    pytest.importorskip("numba")
    from mech import _backend
    from mech.planar.kinematics._fourbar import assembly_gaps, fourbar_lengths

    module = _backend.numba_kernels("fourbar_position")
    rng = np.random.default_rng(16)
    seen = set()
    for trial in range(400):
        lengths = 10.0 ** rng.uniform(-3, 3, 4)
        if trial % 5 == 0:
            lengths[3] = lengths[0] * (1 + 1e-9)        # a ~ d: |BD| all but 0 at theta ~ 0
        if max(lengths) >= sum(lengths) - max(lengths):
            continue
        (a, b, c, d), _ = fourbar_lengths(*lengths)
        gaps = assembly_gaps(a, b, c, d, 1e-12)
        p, q = rng.choice([1.0, 1e150, 1e300]) * rng.uniform(-1, 1, 2)
        theta = rng.uniform(-7, 7, 64)
        theta[:4] = [0.0, 1e-160, -1e-300, 5e-324]
        if trial % 3 == 0:
            theta[rng.integers(64)] = rng.choice([np.nan, np.inf, -np.inf])
        scales = (2.0 ** int(rng.integers(0, 1001)),) * 6 + (1.0,)
        signed = trial % 2 == 1
        kernel = module.fourbar_position_signed_fused_kernel if signed else module.fourbar_position_fused_kernel
        tail = (int(rng.integers(2)), int(rng.integers(2))) if signed else ()
        outs = [np.empty(64) for _ in range(7)]
        valid = np.empty(64, dtype=bool)
        with np.errstate(all="ignore"):
            flag = kernel(a, b, c, d, p, q, theta, 1.0 if trial % 4 else -1.0, *gaps, *tail, scales, *outs, valid)
            every = all(np.isfinite(x).all() for x in outs)
            total = 0.0                                  # the kernel's running sum, in its order
            for i in range(64):
                total += (outs[2][i] + outs[3][i]) + (outs[4][i] + outs[5][i])
        overflow = every and not np.isfinite(total)
        assert flag == (every and not overflow), (trial, lengths, (p, q), scales[0])
        np.testing.assert_array_equal(valid, ~np.isnan(outs[6]))
        # kinds of cases met: a point with C finite and P not (beyond the float range) among them
        only_p = (np.isfinite(outs[2]) & np.isfinite(outs[3]) & ~(np.isfinite(outs[4]) & np.isfinite(outs[5]))).any()
        seen.add((bool(flag), every, bool(only_p)))
    assert {(True, True, False), (False, False, False), (False, False, True)} <= seen, seen

def _run(code, env=None):
    import os

    environment = {k: v for k, v in os.environ.items() if k != "MECH_BACKEND"}
    environment.update(env or {})
    environment["PYTHONPATH"] = str(ROOT)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=environment,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    return done.stdout.strip().splitlines()[-1]


def test_numba_imported_only_when_a_solve_uses_it():
    pytest.importorskip("numba")
    code = (
        "import sys, numpy as np, mech\n"
        "from mech.planar import FourBar\n"
        "f = FourBar(1, 4, 3, 3.5)\n"
        "f.solve(np.linspace(0, 1, 100))\n"           # auto: small, NumPy
        "a = 'numba' in sys.modules\n"
        "mech.set_backend('numba')\n"
        "f.solve(np.linspace(0, 1, 100))\n"
        "print(a, 'numba' in sys.modules)\n"
    )
    assert _run(code) == "False True"


def test_environment_variable_and_switch():
    assert _run("import mech; print(mech.get_backend())", {"MECH_BACKEND": "numpy"}) == "numpy"
    assert _run("import mech; print(mech.get_backend())") == "auto"
    with pytest.raises(ValueError, match="Expected `name` one of 'auto', 'numpy', 'numba', got 'fast'"):
        mech.set_backend("fast")
    with pytest.raises(ValueError, match="`name`.*None"):
        mech.set_backend(None)
