"""Optimisation design (section 4.5): the model, the three solvers, Examples 2-23 and 2-24.

Expected numbers come from independent routes: closed forms of the text's small examples,
mpmath at 50 digits through circle intersections (not the closure or (2-58) of the models),
and `FourBar.solve` for every designed linkage.
"""

import mpmath

import numpy as np
import pytest

from mech._generated.path_optimisation import path_angles, path_coupler_point
from mech.planar.synthesis import (
    CouplerPathDesign,
    DesignModel,
    SteeringTrapezoid,
    grid_search,
    path_synthesis_model,
    penalty_method,
    scipy_minimize,
    steering_trapezoid_model,
)
from mech.planar.synthesis._optimisation_examples import _coupler_model

POINTS_2_24 = np.array([9.50 + 8.26j, 9 + 8.87j, 7.96 + 9.51j, 5.65 + 9.94j, 4.36 + 9.7j, 3.24 + 9j,
                        3.26 + 8.36j, 4.79 + 8.11j, 6.58 + 8j, 9.12 + 7.89j])
# the optimum printed in the text (§2.4 V, after (2-58)), its phi_4 misprinted as phi_A; theta0 is not printed
PRINTED_2_24 = [1.678, 5.819, 5.407, 7.03, 7.973, 2.066, 2.249, np.radians(79.016), np.radians(-70.29)]
# a rough start, as a graphical design would give (the printed design rounded)
START_2_24 = np.array([1.7, 5.8, 5.4, 7.0, 8.0, 2.0, 2.2, np.radians(80), np.radians(-70), np.radians(90)])


# ---------------------------------------------------------------- independent oracles

def _circle_intersection(c1, r1, c2, r2, side):
    """Intersection of two circles (mpmath complex), the one to the `side` (+1 left) of c1->c2."""
    d = abs(c2 - c1)
    along = (r1**2 - r2**2 + d**2) / (2 * d)
    across = mpmath.sqrt(r1**2 - along**2)
    u = (c2 - c1) / d
    return c1 + u * (along + side * 1j * across)


def _steering_objective_mp(l1, phi0, a=1480, h=2960, steps=20, theta_max=mpmath.radians(30)):
    """Example 2-23's objective: C from circle intersection (not the closure), mpmath 50 digits."""
    with mpmath.workdps(50):
        l1, phi0, a, h = (mpmath.mpf(v) for v in (l1, phi0, a, h))
        l2 = a - 2 * l1 * mpmath.cos(phi0)
        D = mpmath.mpc(a, 0)
        total = mpmath.mpf(0)
        for i in range(steps + 1):
            th = theta_max * i / steps
            B = l1 * mpmath.expj(phi0 + th)
            # C lies on the circle about D of radius l1 and about B of radius l2, left of B->D
            C = _circle_intersection(B, l2, D, l1, +1)
            beta = mpmath.arg(C - D) - mpmath.pi + phi0
            ideal = mpmath.atan(mpmath.tan(th) / (1 - (a / h) * mpmath.tan(th)))
            w = mpmath.mpf(0.5) if i in (0, steps) else mpmath.mpf(1)
            total += w * (ideal - beta) ** 2 * theta_max / steps
        return float(total)


def _coupler_points_mp(x, n):
    """Coupler points of a 2-24 design by circle intersection at 50 digits."""
    with mpmath.workdps(50):
        l1, l2, l3, l4, l5, xa, ya, alpha, phi4, theta0 = (mpmath.mpf(float(v)) for v in x)
        A = mpmath.mpc(xa, ya)
        D = A + l4 * mpmath.expj(phi4)
        out = []
        for k in range(n):
            B = A + l1 * mpmath.expj(phi4 + theta0 + 2 * mpmath.pi * k / n)
            C = _circle_intersection(B, l2, D, l3, +1)
            out.append(complex(B + l5 * mpmath.expj(alpha) * (C - B) / l2))
        return np.array(out)


# ---------------------------------------------------------------- the text's small examples

def _qp(equality=True):
    """The illustrative problem of §2.4 V (Fig. 2-110)."""
    def h(x):
        x1, x2 = x[..., 0], x[..., 1]
        return (73 * x1**2 + 52 * x2**2 + 72 * x1 * x2 - 356 * x1 - 292 * x2 + 433)[..., None]

    return DesignModel(lambda x: ((x - 2.0) ** 2).sum(-1), [(-1, 3), (-1, 3)],
                       inequality=lambda x: np.stack([-x[..., 0], -x[..., 1], (x**2).sum(-1) - 4.0], -1),
                       equality=h if equality else None)


def test_scipy_minimize_textbook_points_B_and_C():
    """Fig. 2-110: B = (sqrt 2, sqrt 2), f = 2 (2 - sqrt 2)^2; C = (0.8, 1.1), f = 2.25."""
    b = scipy_minimize(_qp(equality=False), [0.5, 0.5], options={"ftol": 1e-14})
    assert np.allclose(b.x, np.sqrt(2), atol=1e-7) and abs(b.fun - 2 * (2 - np.sqrt(2)) ** 2) < 1e-9
    # the circle f = 2.25 osculates the ellipse at C (f - 2.25 grows as the 4th power of the
    # distance along it), so x is found only to about the 4th root of the tolerance
    c = scipy_minimize(_qp(), [1.0, 1.0], options={"ftol": 1e-12, "maxiter": 1000})
    assert np.allclose(c.x, [0.8, 1.1], atol=1e-5) and abs(c.fun - 2.25) < 1e-10
    assert np.all(c.g <= 1e-12) and abs(c.h[0]) < 1e-9
    # C is the best feasible point of the ellipse h = 0 (dense sampling, another route):
    # centre (1.6, 1.7), semi-axes 2 and 1 along the eigenvectors of [[73, 36], [36, 52]]
    w, v = np.linalg.eigh([[73.0, 36.0], [36.0, 52.0]])
    t = np.linspace(0, 2 * np.pi, 200001)
    e = np.array([1.6, 1.7])[:, None] + v @ (np.array([np.cos(t), np.sin(t)]) * (10 / np.sqrt(w))[:, None])
    assert np.max(np.abs(_qp().h(e.T))) < 1e-9
    feasible = (e[0] >= 0) & (e[1] >= 0) & ((e**2).sum(0) <= 4)
    assert np.min(((e - 2.0) ** 2).sum(0)[feasible]) > c.fun - 1e-6


def test_penalty_method_textbook_example_one_stage():
    """§2.4 V: phi = x - r/(1 - x) is least at 1 + sqrt(r); the box (-5, 5) adds r/(5 + x) + r/(5 - x)."""
    model = DesignModel(lambda x: x[..., 0], [(-5, 5)], inequality=lambda x: 1.0 - x)
    for r in (1e-2, 1e-4, 1e-6):
        got = penalty_method(model, [3.0], r0=r, stages=1, ftol=0, xtol=1e-15).x[0]
        with mpmath.workdps(50):
            rr = mpmath.mpf(r)
            dphi = lambda x: 1 - rr / (x - 1) ** 2 - rr / (5 + x) ** 2 + rr / (5 - x) ** 2
            want = mpmath.findroot(dphi, 1 + mpmath.sqrt(rr))
        assert abs(got - float(want)) < 1e-9 * float(want)
        assert abs(float(want) - (1 + np.sqrt(r))) < 10 * r            # the text's closed form, box aside


def test_penalty_method_converges_to_constrained_optimum():
    """Point B of Fig. 2-110 from inside, and C with the exterior term for h."""
    b = penalty_method(_qp(equality=False), [0.5, 0.5], factor=0.1, stages=10)
    assert np.allclose(b.x, np.sqrt(2), atol=1e-4) and np.all(b.g < 0)
    c = penalty_method(_qp(), [0.5, 0.5], r0=1e-2, factor=0.1, stages=8)
    assert np.allclose(c.x, [0.8, 1.1], atol=1e-3)


# ---------------------------------------------------------------- Example 2-23

def test_example_2_23_grid_optimum():
    """Ex. 2-23 by the grid method: l1 = 148 mm (on its bound), phi0 = 1.2263 rad, f = 2.5626e-5."""
    model = steering_trapezoid_model()
    res = grid_search(model, points=21, levels=40)
    assert res.x[0] == 148.0 and res.g[0] == 0.0                  # g1 active: 0.1 a = 148 mm
    assert abs(res.x[1] - 1.22630) < 5e-5 and np.all(res.g <= 0)
    want = _steering_objective_mp(*res.x)
    assert abs(res.fun - want) < 1e-10 * want
    assert abs(res.fun - 2.5626e-5) < 1e-9                         # the text: 2.56e-5
    # proved by analysis: FourBar.solve gives the same beta and objective
    proof = SteeringTrapezoid(*res.x).prove()
    assert proof.valid and proof.model_difference < 1e-12
    assert abs(proof.objective - want) < 1e-10 * want
    assert np.degrees(proof.min_transmission_angle) > 20
    # no better point on the active bound (a dense scan of phi0, independent of the grid)
    phi = np.linspace(model.bounds[1, 0], model.bounds[1, 1], 20001)
    assert res.fun <= np.min(model.f(np.stack([np.full_like(phi, 148.0), phi], -1))) + 1e-15


def test_example_2_23_methods_agree():
    model = steering_trapezoid_model()
    grid = grid_search(model, points=21, levels=40)
    pen = penalty_method(model, [300.0, 1.4], factor=0.1, stages=10)
    sq = scipy_minimize(model, [300.0, 1.4], options={"ftol": 1e-14})
    for res in (pen, sq):
        assert np.all(res.g <= 1e-9) and abs(res.fun - grid.fun) < 1e-4 * grid.fun
        assert abs(res.x[0] - 148.0) < 0.05 and abs(res.x[1] - grid.x[1]) < 1e-4


def test_example_2_23_printed_constant_is_wrong():
    """Errata: the printed C gives beta(0) = -1.4305 rad (-82 deg) instead of 0; the printed bounds are in cm."""
    l1, phi0, a, th = 148.0, 1.226, 1480.0, 0.0
    A = 2 * l1**2 * np.sin(phi0 + th)
    B = 2 * l1**2 * np.cos(phi0 + th) - 2 * a * l1
    printed = 2 * l1**2 + 2 * a * l1 * np.cos(phi0) - 4 * l1**2 * np.cos(phi0) ** 2 - 2 * a * l1 * (phi0 + th)
    correct = 2 * l1**2 + 4 * a * l1 * np.cos(phi0) - 4 * l1**2 * np.cos(phi0) ** 2 - 2 * a * l1 * np.cos(phi0 + th)
    beta = [np.arctan2(A, B) - np.arccos(c / np.hypot(A, B)) - np.pi + phi0 for c in (printed, correct)]
    assert abs(beta[1]) < 1e-12 and abs(beta[0] + 1.4305) < 1e-4
    # 14.8 <= l1 <= 59.2 (as printed) would admit a shorter arm than 0.1 a = 148 mm
    assert steering_trapezoid_model().bounds[0].tolist() == [148.0, 592.0]


@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1.0, 1e150, 1e300])
def test_example_2_23_scale_invariant(scale):
    model = steering_trapezoid_model(1480 * scale, 2960 * scale)
    ref = steering_trapezoid_model().f([148.0, 1.226])
    assert abs(model.f([148 * scale, 1.226]) - ref) < 1e-13 * ref
    proof = SteeringTrapezoid(148 * scale, 1.226, 1480 * scale, 2960 * scale).prove()
    assert proof.valid and abs(proof.objective - ref) < 1e-11 * ref


# ---------------------------------------------------------------- Example 2-24

def test_example_2_24_printed_design_by_analysis():
    """The printed optimum: best start angle 92.09 deg, sum of distances 1.88997, gamma_min 56.80 deg."""
    theta0 = np.radians(np.linspace(0, 360, 36001))
    X = np.array([PRINTED_2_24 + [t] for t in theta0])
    f = path_synthesis_model(POINTS_2_24).f(X)
    k = int(np.argmin(f))
    assert abs(np.degrees(theta0[k]) - 92.09) < 0.011
    proof = CouplerPathDesign(X[k], POINTS_2_24).prove(samples=72000)
    assert proof.valid and proof.kind == "crank-rocker"
    assert abs(proof.objective - f[k]) < 1e-12 * f[k] and abs(proof.objective - 1.88997) < 1e-5
    assert np.allclose(proof.P, _coupler_points_mp(X[k], 10), rtol=0, atol=1e-12)
    assert abs(np.degrees(proof.min_transmission_angle) - 56.8042) < 1e-3
    # the coupler curve passes near every point: distances of the curve from the ten points
    near = [0.0002, 0.0034, 0.156, 0.223, 0.093, 0.097, 0.139, 0.0022, 0.101, 0.0038]
    assert np.allclose(proof.curve_distances, near, atol=6e-4)


def test_example_2_24_penalty_method_by_analysis():
    model = path_synthesis_model(POINTS_2_24)
    res = penalty_method(model, START_2_24)
    assert np.all(res.g < 0) and res.fun < 1.8                      # better than the printed 1.88997
    design = CouplerPathDesign(res.x, POINTS_2_24)
    proof = design.prove()
    assert proof.valid and proof.kind == "crank-rocker"
    # distances measured by analysis (FourBar.solve), checked against circle intersections
    assert np.allclose(proof.P, _coupler_points_mp(res.x, 10), rtol=0, atol=1e-12)
    assert abs(proof.objective - res.fun) < 1e-12 * res.fun
    assert proof.min_transmission_angle >= np.radians(30)
    # the history is a convergence curve: evaluations increase, objective ends at the optimum
    assert np.all(np.diff(res.history[:, 0]) > 0) and res.history[-1, 1] == pytest.approx(res.fun, rel=1e-12)


@pytest.mark.parametrize("scale", [1e-300, 1.0, 1e300])
def test_example_2_24_scale_invariant(scale):
    x = np.array(PRINTED_2_24 + [np.radians(92.09)])
    xs = x.copy()
    xs[:7] *= scale
    ref = path_synthesis_model(POINTS_2_24).f(x)
    got = path_synthesis_model(POINTS_2_24 * scale).f(xs) / scale
    assert abs(got - ref) < 1e-13 * ref
    assert abs(CouplerPathDesign(xs, POINTS_2_24 * scale).prove().objective / scale - ref) < 1e-12 * ref


# ---------------------------------------------------------------- the model (2-58), generated code

def _local_delta_mp(l1, l2, l3, l4, phi1):
    """Angle of B->C from A->D at 50 digits, C by circle intersection left of B->D."""
    with mpmath.workdps(50):
        l1, l2, l3, l4, phi1 = (mpmath.mpf(float(v)) for v in (l1, l2, l3, l4, phi1))
        B = l1 * mpmath.expj(phi1)
        C = _circle_intersection(B, l2, mpmath.mpc(l4, 0), l3, +1)
        return mpmath.arg(C - B)


def _textbook_delta(l1, l2, l3, l4, phi1):
    """delta of (2-58) as printed: law-of-cosines d, arccos and arcsin, in double precision."""
    d = np.sqrt(l1 * l1 + l4 * l4 - 2.0 * l1 * l4 * np.cos(phi1))
    with np.errstate(invalid="ignore"):
        return np.arccos((l2 * l2 + d * d - l3 * l3) / (2.0 * l2 * d)) - np.arcsin(l1 * np.sin(phi1) / d)


def _near_fold_designs(gap, count, seed):
    """Crank-rockers on a 2^-10 grid with one Grashof gap = 2^-k (k = 30..44), exact in binary,
    and the crank angle near the pose where that gap folds the triangle BCD (phi1 = 0 or pi)."""
    rng = np.random.default_rng(seed)
    grid = lambda lo, hi: np.round(rng.uniform(lo, hi) * 1024) / 1024
    out = []
    for _ in range(count):
        eps = 2.0 ** -rng.integers(30, 45)
        t = rng.choice([-1, 1]) * 10.0 ** rng.uniform(-12, -6)
        l1, l4 = grid(0.5, 1.0), grid(3.0, 3.5)
        if gap == "g4":      # l2 + l3 = l1 + l4 + eps: kappa near 0 at phi1 = pi (C between B and D)
            l2 = grid(1.5, 2.5)
            out.append((l1, l2, l1 + l4 - l2 + eps, l4, np.pi + t))
        elif gap == "g3":    # l2 = l3 + (l4 - l1) - eps: kappa near 0 at phi1 = 0 (C beyond D)
            l3 = grid(1.5, 2.5)
            out.append((l1, l3 + l4 - l1 - eps, l3, l4, t))
        else:                # l3 = l2 + (l4 - l1) - eps: kappa near pi at phi1 = 0 (B between C and D)
            l2 = grid(1.5, 2.5)
            out.append((l1, l2, l2 + l4 - l1 - eps, l4, t))
    return np.array(out)


def test_path_coupler_point_mpmath_random():
    """The generated (2-58) against circle intersections at 50 digits on random crank-rockers,
    and against the ten-argument placement of FourBar's coupler point."""
    rng = np.random.default_rng(2058)
    m = 300
    x = np.column_stack([rng.uniform(0.2, 1.0, m), rng.uniform(2.0, 3.5, m), rng.uniform(2.0, 3.5, m),
                         rng.uniform(3.0, 3.5, m), rng.uniform(0.0, 5.0, m), rng.uniform(-10, 10, (m, 2)),
                         rng.uniform(-np.pi, np.pi, (m, 3))])
    x = x[(x[:, 0] + x[:, 3] <= x[:, 1] + x[:, 2]) & (x[:, 0] + x[:, 1] <= x[:, 2] + x[:, 3])
          & (x[:, 0] + x[:, 2] <= x[:, 1] + x[:, 3])]
    xp, yp = path_coupler_point(*x.T)
    want = _coupler_points_mp_at(x)
    err = np.abs(xp + 1j * yp - want) / (np.abs(x[:, 5] + 1j * x[:, 6]) + x[:, 0] + x[:, 4])
    assert x.shape[0] > 150 and np.max(err) < 4e-16
    # the package's model is the same function, vectorised over designs and steps
    model = _coupler_model(np.column_stack([x[:, :9], x[:, 9]])[:, None, :], 1)[:, 0, 0]
    assert np.max(np.abs(model - want) / (np.abs(want) + x[:, 0] + x[:, 4])) < 1e-15


def _coupler_points_mp_at(x):
    out = []
    for row in x:
        out.append(_coupler_points_mp(list(row), 1)[0])
    return np.array(out)


@pytest.mark.parametrize("gap", ["g2", "g3", "g4"])
def test_path_angles_near_folds_atan2_vs_arccos(gap):
    """Near a flat triangle BCD (kappa near 0 or pi) the atan2 form of delta keeps rounding
    accuracy; the printed arccos form has an absolute error of about eps over the distance
    to the fold."""
    designs = _near_fold_designs(gap, 40, seed={"g2": 2, "g3": 3, "g4": 4}[gap])
    _, beta, delta = path_angles(*designs.T)
    ref = np.array([float(_local_delta_mp(*row)) for row in designs])
    scale = np.abs(ref) + np.abs(beta)
    err_atan2 = np.abs(np.angle(np.exp(1j * (delta - ref)))) / scale
    printed = _textbook_delta(*designs.T)
    err_acos = np.abs(np.angle(np.exp(1j * (printed - ref)))) / scale
    err_acos = np.where(np.isnan(printed), np.inf, err_acos)
    assert np.max(err_atan2) < 4 * np.finfo(float).eps       # measured: at most 1.6 eps
    # the printed form is off by far more than rounding on most of these designs
    eps = np.finfo(float).eps
    assert np.median(err_acos) > 1e3 * eps and np.max(err_acos) > 1e5 * eps


def test_path_angles_beta_is_the_printed_arcsin_for_a_crank():
    """beta by atan2 equals the text's arcsin(l1 sin(phi1) / d) when l1 < l4 (F52, F31)."""
    rng = np.random.default_rng(31)
    l1, l4, phi1 = rng.uniform(0.2, 1.0, 500), rng.uniform(1.1, 3.0, 500), rng.uniform(-np.pi, np.pi, 500)
    d, beta, _ = path_angles(l1, 2.0, 2.0, l4, phi1)
    assert np.allclose(beta, np.arcsin(l1 * np.sin(phi1) / d), rtol=0, atol=1e-14)
    assert np.allclose(d, np.sqrt(l1**2 + l4**2 - 2 * l1 * l4 * np.cos(phi1)), rtol=1e-14)


def test_path_coupler_point_broadcast_and_unassembled():
    """Shapes broadcast like a ufunc; a design that cannot be assembled gives NaN, never a wrong point."""
    phi1 = np.linspace(0, 2 * np.pi, 12).reshape(3, 4)
    xp, yp = path_coupler_point(1.0, 3.0, 3.0, 3.2, 1.5, 0.0, 0.0, 0.3, 0.1, phi1)
    assert xp.shape == yp.shape == (3, 4) and np.all(np.isfinite(xp))
    with np.errstate(invalid="ignore"):
        xp, _ = path_coupler_point(1.0, 1.0, 1.0, 3.5, 1.0, 0.0, 0.0, 0.0, 0.0, np.array([0.0, np.pi]))
    assert np.all(np.isnan(xp))


# ---------------------------------------------------------------- checkpoints and progress

class _Interrupt(Exception):
    pass


def _interrupting(model, after):
    """The same model, but its objective raises after `after` calls (a stopped run)."""
    calls = [0]

    def objective(x):
        calls[0] += 1
        if calls[0] > after:
            raise _Interrupt
        return model.objective(x)

    return DesignModel(objective, model.bounds, inequality=model.inequality, equality=model.equality,
                       names=model.names)


def _same(a, b):
    assert np.array_equal(a.x, b.x) and a.fun == b.fun and a.evaluations == b.evaluations
    assert np.array_equal(a.history, b.history)


def test_grid_search_checkpoint_resume(tmp_path):
    model = steering_trapezoid_model()
    full = grid_search(model, points=15, levels=12)
    path = tmp_path / "grid.npz"
    with pytest.raises(ValueError, match="_Interrupt"):
        grid_search(_interrupting(model, 7), points=15, levels=12, checkpoint=path, every=2)
    assert path.exists()
    _same(grid_search(model, points=15, levels=12, checkpoint=path, every=2), full)


def test_penalty_method_checkpoint_resume(tmp_path):
    model = path_synthesis_model(POINTS_2_24)
    kw = dict(stages=3, iterations=300)
    full = penalty_method(model, START_2_24, **kw)
    path = tmp_path / "penalty.npz"
    with pytest.raises(ValueError, match="_Interrupt"):
        penalty_method(_interrupting(model, full.evaluations // 2), START_2_24, checkpoint=path, every=25, **kw)
    with np.load(path) as saved:
        assert int(saved["evaluations"]) < full.evaluations // 2       # stopped half-way
    _same(penalty_method(model, START_2_24, checkpoint=path, every=25, **kw), full)


def test_penalty_method_ctrl_c_then_resume(tmp_path):
    """A KeyboardInterrupt (Ctrl-C) in the middle is not masked; the checkpoint it leaves
    resumes to the result of an uninterrupted run."""
    model = path_synthesis_model(POINTS_2_24)
    kw = dict(stages=2, iterations=200)
    full = penalty_method(model, START_2_24, **kw)
    calls = [0]

    def objective(x):
        calls[0] += 1
        if calls[0] > full.evaluations // 2:
            raise KeyboardInterrupt
        return model.objective(x)

    stopped = DesignModel(objective, model.bounds, inequality=model.inequality, equality=model.equality,
                          names=model.names)
    path = tmp_path / "ctrl-c.npz"
    with pytest.raises(KeyboardInterrupt):
        penalty_method(stopped, START_2_24, checkpoint=path, every=20, **kw)
    assert path.exists()
    _same(penalty_method(model, START_2_24, checkpoint=path, every=20, **kw), full)


def test_checkpoint_of_another_search_is_refused(tmp_path):
    path = tmp_path / "grid.npz"
    grid_search(steering_trapezoid_model(), points=5, levels=2, checkpoint=path)
    with pytest.raises(ValueError, match="Expected `checkpoint`"):
        grid_search(steering_trapezoid_model(), points=7, levels=2, checkpoint=path)
    with pytest.raises(ValueError, match="Expected `checkpoint`"):
        penalty_method(steering_trapezoid_model(), [300.0, 1.4], checkpoint=path)


def test_progress_bar_on_stderr_in_a_terminal_and_stdout_in_a_kernel(capsys, monkeypatch):
    grid_search(steering_trapezoid_model(), points=5, levels=3, progress=True)
    out, err = capsys.readouterr()
    assert out == "" and "grid" in err
    # in a Jupyter kernel any standard error fails the strict book build: the bar goes to stdout
    import mech._progress

    monkeypatch.setattr(mech._progress, "_in_kernel", lambda: True)
    grid_search(steering_trapezoid_model(), points=5, levels=3, progress=True)
    penalty_method(steering_trapezoid_model(), [300.0, 1.4], stages=1, iterations=20, progress=True)
    out, err = capsys.readouterr()
    assert err == "" and "grid" in out and "penalty" in out


# ---------------------------------------------------------------- bad input

def test_design_model_rejects_bad_input():
    f = lambda x: x.sum(-1)
    with pytest.raises(ValueError, match="Expected `bounds`"):
        DesignModel(f, [(1, 0)])
    with pytest.raises(ValueError, match="Expected finite `bounds`"):
        DesignModel(f, [(0, np.inf)])
    with pytest.raises(ValueError, match="Expected `objective`"):
        DesignModel(3.0, [(0, 1)])
    with pytest.raises(ValueError, match="Expected `names`"):
        DesignModel(f, [(0, 1)], names=("a", "b"))
    with pytest.raises(ValueError, match="Expected `objective` to evaluate"):
        DesignModel(lambda x: 1 / 0, [(0, 1)]).f([0.5])
    with pytest.raises(ValueError, match="Expected `objective` of shape"):
        DesignModel(lambda x: x, [(0, 1), (0, 1)]).f([0.5, 0.5])
    with pytest.raises(ValueError, match="Expected `x`"):
        DesignModel(f, [(0, 1)]).f([1j])


def test_solvers_reject_bad_input():
    model = steering_trapezoid_model()
    with pytest.raises(ValueError, match="Expected `x0` strictly inside"):
        penalty_method(model, [100.0, 1.4])
    with pytest.raises(ValueError, match="Expected `points` odd"):
        grid_search(model, points=4)
    with pytest.raises(ValueError, match="Expected `shrink`"):
        grid_search(model, shrink=1.0)
    with pytest.raises(ValueError, match="Expected `model` without equality"):
        grid_search(_qp())
    with pytest.raises(ValueError, match="Expected `points` \\*\\* n"):
        grid_search(path_synthesis_model(POINTS_2_24))
    with pytest.raises(ValueError, match="Expected `method`"):
        scipy_minimize(model, [300.0, 1.4], method="BFGS")
    with pytest.raises(ValueError, match="Expected `factor`"):
        penalty_method(model, [300.0, 1.4], factor=2.0)
    with pytest.raises(ValueError, match="Expected `points`"):
        path_synthesis_model([1, 2])
    with pytest.raises(ValueError, match="Expected finite `points`"):
        path_synthesis_model([1, 2, np.nan])
    with pytest.raises(ValueError, match="Expected `l1`"):
        SteeringTrapezoid(-1.0, 1.2)
    with pytest.raises(ValueError, match="Expected `l1` < a"):
        SteeringTrapezoid(1000.0, 0.2)
    with pytest.raises(ValueError, match="Expected `x`"):
        CouplerPathDesign(START_2_24[:9], POINTS_2_24)


@pytest.mark.parametrize("scale", [1e-300, 1e300])
def test_grid_search_scale_invariant(scale):
    """The grid method on Example 2-23 in any unit of length finds the same design."""
    ref = grid_search(steering_trapezoid_model(), points=11, levels=30)
    got = grid_search(steering_trapezoid_model(1480 * scale, 2960 * scale), points=11, levels=30)
    assert abs(got.x[0] / scale - ref.x[0]) < 1e-12 * ref.x[0] and abs(got.x[1] - ref.x[1]) < 1e-12
    assert abs(got.fun - ref.fun) < 1e-12 * ref.fun


def test_design_model_feasible():
    model = _qp(equality=False)
    x = np.array([[1.0, 1.0], [1.9, 1.9], [-0.5, 1.0], [3.5, 0.0]])
    assert model.feasible(x).tolist() == [True, False, False, False]
    assert model.feasible([2.0, 0.0]).item() and not model.feasible([2.0, 0.1]).item()
    assert model.feasible([2.0, 0.1], tol=0.02).item()
