"""Centric slider-cranks for four poses, eqs. (2-42) (Fig. 2-91), against the raw equations.

Oracle: the six printed equations (2-42) in the six unknowns A, B_1, C_1, solved from many
random starts (SciPy's `fsolve` in double precision, then mpmath's `findroot` at 30 digits
from each converged point), with the spurious family C_1 = A (which satisfies the first
line of (2-42) for any C) set aside. No slider point, no cubic: the full real solution set
found that way must equal the package's. Every design is then moved by `SliderCrank`.
"""

import mpmath as mp
import numpy as np
import pytest
from scipy.optimize import fsolve

from mech import InputTypeError
from mech.planar import SliderCrank
from mech.planar.synthesis import CentricSliderCrank, GuidanceSliderCrank, centric_slider_cranks

P_2_15 = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j])
THETA_2_15 = np.radians([0.0, 8.88, 22.1, 63.68])


def _raw_2_42(theta, d, X, lib=np):
    """The six residuals of (2-42), as printed (collinearity of A, C_1, C_j; equal crank lengths)."""
    xa, ya, xb, yb, xc, yc = X
    out = []
    for j in range(1, 4):          # C_j = [P]_j1 C_1, B_j = [P]_j1 B_1 (the pose convention)
        c, s = lib.cos(theta[j] - theta[0]), lib.sin(theta[j] - theta[0])
        rx, ry = xc - d[0].real, yc - d[0].imag
        xcj, ycj = c * rx - s * ry + d[j].real, s * rx + c * ry + d[j].imag
        out.append((ycj - ya) * (xc - xa) - (yc - ya) * (xcj - xa))
    for j in range(1, 4):
        c, s = lib.cos(theta[j] - theta[0]), lib.sin(theta[j] - theta[0])
        rx, ry = xb - d[0].real, yb - d[0].imag
        xbj, ybj = c * rx - s * ry + d[j].real, s * rx + c * ry + d[j].imag
        out.append((xbj - xa) ** 2 + (ybj - ya) ** 2 - (xb - xa) ** 2 - (yb - ya) ** 2)
    return out


def raw_solutions(theta, d, *, starts=600, seed=0):
    """Every real non-degenerate root of (2-42) found from `starts` random starts.

    Roots are compared in a frame moved to the poses' centroid and scaled by their size;
    each converged double-precision root is refined by mpmath at 30 digits.
    """
    centre = d.mean()
    size = float(np.max(np.abs(d - centre)))
    dn = (d - centre) / size
    rng = np.random.default_rng(seed)
    mp.mp.dps = 30
    tm = [mp.mpf(float(t)) for t in theta]
    dm = [mp.mpc(complex(p)) for p in dn]
    found = []
    for _ in range(starts):
        radius = 10.0 ** rng.uniform(-1.0, 1.5, 3)
        pts = radius * np.exp(2j * np.pi * rng.uniform(size=3))
        x0 = np.array([pts[0].real, pts[0].imag, pts[1].real, pts[1].imag, pts[2].real, pts[2].imag])
        x, info, ier, _ = fsolve(lambda X: _raw_2_42(theta, dn, X), x0, full_output=True, xtol=1e-13)
        A, B1, C1 = complex(x[0], x[1]), complex(x[2], x[3]), complex(x[4], x[5])
        if ier != 1 or abs(C1 - A) < 1e-4 or abs(B1 - A) < 1e-4 or max(abs(A), abs(B1), abs(C1)) > 1e4:
            continue
        if any(abs(A - f[0]) < 1e-6 * max(1.0, abs(A)) for f in found):
            continue
        r = mp.findroot(lambda *X: _raw_2_42(tm, dm, X, lib=mp), [mp.mpf(float(v)) for v in x], tol=1e-50)
        r = [complex(r[k]) for k in range(6)]
        found.append((complex(r[0].real, r[1].real), complex(r[2].real, r[3].real), complex(r[4].real, r[5].real)))
    return [(centre + size * A, centre + size * B1, centre + size * C1) for A, B1, C1 in found]


def centric_poses(a, b, phi, origin=0j, turn=0.0, body=(0.3 + 0.8j, 0.4)):
    """Coupler poses of a centric slider-crank (crank a, rod b) at crank angles `phi`, placed.

    The body frame sits at `body[0]` in the rod's frame (B at 0, C on +x) turned by `body[1]`.
    """
    B = a * np.exp(1j * np.asarray(phi, dtype=float))
    C = B.real + np.sqrt(b * b - B.imag**2)
    rod = np.angle(C - B)
    w = np.exp(1j * turn)
    theta = rod + body[1] + turn
    return theta, origin + w * (B + np.exp(1j * rod) * body[0])


def _match(designs, raw, size):
    got = sorted((k.crank.centre_point for k in designs), key=lambda z: (z.real, z.imag))
    want = sorted((r[0] for r in raw), key=lambda z: (z.real, z.imag))
    assert len(got) == len(want), (got, want)
    for g, w in zip(got, want):
        assert abs(g - w) <= 1e-9 * max(size, abs(w))
        k = next(k for k in designs if k.crank.centre_point == g)
        r = next(r for r in raw if r[0] == w)
        assert abs(k.crank.moving_pivot - r[1]) <= 1e-9 * max(size, abs(r[1]))
        assert abs(k.slider.moving_pivot - r[2]) <= 1e-9 * max(size, abs(r[2]))


def _proved(k, theta, d, rtol=1e-9):
    """Move the design with SliderCrank through its input angles: the poses, to rtol."""
    assert isinstance(k, CentricSliderCrank) and isinstance(k.guidance, GuidanceSliderCrank)
    assert k.slider_crank.e == 0.0
    t_rec, d_rec = k.coupler_poses(k.theta_input)
    size = max(k.slider_crank.a, k.slider_crank.b, float(np.max(np.abs(d - k.origin))))
    err = max(np.max(np.abs(d_rec - d)) / size, np.max(np.abs(np.angle(np.exp(1j * (t_rec - theta))))))
    assert err <= rtol and k.pose_error <= rtol
    # the guide (the x axis of the standard frame) passes through A and carries C at every pose
    C = np.exp(-1j * k.angle) * (np.exp(1j * theta) * k.slider.slider_point + d - k.origin)
    assert np.max(np.abs(C.imag)) <= rtol * size
    return err


def test_example_2_15_first_four_poses():
    """Example 2-15, poses 1-4 (§2.4 I), as a centric slider-crank (Fig. 2-91, (2-42))."""
    designs = centric_slider_cranks(THETA_2_15, P_2_15)
    raw = raw_solutions(THETA_2_15, P_2_15)
    _match(designs, raw, 150.0)
    (k,) = designs
    assert k.passes and k.guidance.passes
    assert _proved(k, THETA_2_15, P_2_15) <= 1e-12
    assert k.slider_crank.a == pytest.approx(211.3475, abs=1e-4)
    # beta of (F84): the guide from A towards C_1
    assert np.exp(1j * k.angle) == pytest.approx((k.slider.moving_pivot - k.origin)
                                                 / abs(k.slider.moving_pivot - k.origin), abs=1e-14)


CASES = [  # a, b, crank angles, origin, turn
    (1.0, 3.0, [0.2, 0.9, 1.6, 2.5], 0j, 0.0),
    (2.0, 2.6, [-0.4, 0.5, 1.1, 2.0], 3 - 1j, 0.7),
    (1.0, 4.5, [0.3, 1.2, 2.0, 3.0], -2 + 5j, -2.0),
    (50.0, 120.0, [1.0, 1.5, 2.6, 4.0], 100 + 40j, 2.5),
]


@pytest.mark.parametrize("a, b, phi, origin, turn", CASES)
def test_known_centric_slider_crank_is_found(a, b, phi, origin, turn):
    """Poses of a known centric slider-crank: it is among the solutions, which equal the raw roots."""
    theta, d = centric_poses(a, b, phi, origin, turn)
    designs = centric_slider_cranks(theta, d)
    size = float(np.max(np.abs(d - d.mean())))
    _match(designs, raw_solutions(theta, d, seed=1), size)
    known = [k for k in designs if abs(k.origin - origin) <= 1e-9 * max(a, b)]
    assert len(known) == 1
    k = known[0]
    assert k.slider_crank.a == pytest.approx(a, rel=1e-9) and k.slider_crank.b == pytest.approx(b, rel=1e-9)
    assert k.passes
    for k in designs:
        if k.passes:
            _proved(k, theta, d)


@pytest.mark.parametrize("seed", range(6))
def test_random_pose_sets_match_the_raw_equations(seed):
    rng = np.random.default_rng(seed)
    theta = np.sort(rng.uniform(-1.5, 1.5, 4))
    d = rng.normal(size=4) + 1j * rng.normal(size=4)
    designs = centric_slider_cranks(theta, d)
    _match(designs, raw_solutions(theta, d, seed=seed), float(np.max(np.abs(d - d.mean()))))
    for k in designs:
        assert k.pose_error <= 1e-9 or not k.passes
        if k.passes:
            _proved(k, theta, d)


@pytest.mark.parametrize("scale", [1e-100, 1e100])
def test_designs_scale_with_the_unit(scale):
    theta, d = centric_poses(1.0, 3.0, [0.2, 0.9, 1.6, 2.5], 0.5 + 0.5j, 0.3)
    ref = centric_slider_cranks(theta, d)
    scaled = centric_slider_cranks(theta, d * scale)
    assert len(ref) == len(scaled)
    for k, s in zip(ref, scaled):
        assert s.slider_crank.a == pytest.approx(k.slider_crank.a * scale, rel=1e-12)
        assert s.passes == k.passes


def test_solution_moved_by_slider_crank_directly():
    """The standard-frame SliderCrank, placed, reproduces pose 1's pins."""
    (k,) = centric_slider_cranks(THETA_2_15, P_2_15)
    sol = SliderCrank(k.slider_crank.a, k.slider_crank.b, 0.0, branch=k.slider_crank.branch).solve(k.theta_input)
    assert np.allclose(k.to_ground(sol.B), np.exp(1j * THETA_2_15) * k.crank.circle_point + P_2_15, atol=1e-9)
    assert np.allclose(k.to_ground(sol.C), np.exp(1j * THETA_2_15) * k.slider.slider_point + P_2_15, atol=1e-9)


@pytest.mark.parametrize("kwargs, name", [
    (dict(theta=THETA_2_15[:3], d=P_2_15[:3]), "theta"),
    (dict(theta=THETA_2_15, d=P_2_15[:3]), "theta"),
    (dict(theta=THETA_2_15, d=np.array([np.nan, 1, 2, 3])), "d"),
    (dict(theta=THETA_2_15, d=P_2_15, rtol=-1.0), "rtol"),
    (dict(theta=THETA_2_15, d=P_2_15, imag_tol=float("inf")), "imag_tol"),
])
def test_bad_inputs_name_the_argument(kwargs, name):
    with pytest.raises(ValueError, match=f"`{name}`"):
        centric_slider_cranks(**kwargs)


def test_type_errors_are_input_type_errors():
    with pytest.raises(InputTypeError):
        centric_slider_cranks("0 1 2 3", P_2_15)
