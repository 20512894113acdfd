"""`RSSR.solve` as one compiled loop over the crank angles (the numba backend).

The loop calls numba-compiled copies of the same generated functions as the NumPy path
(``mech._generated.rssr`` and ``one_equation``) on scalars, pose by pose, with the same
rules: the factored discriminant where the reach is real, a radicand within
``DEAD_POINT_RTOL`` of zero snapped onto the limit position, NaN rates there. The
arithmetic is the same sequence of operations; only ``sin``, ``cos``, ``hypot`` and
``atan2`` may come from another library (LLVM's libm calls instead of NumPy's vectorised
ones), so the results agree with the NumPy path to within a few ulp (the tests allow 8
ulp of the largest dimension for points, 8 ulp of pi for angles). Linkages with change
points (`mech.spatial._rssr_change`) stay on NumPy.

This module imports numba: it is imported only when a solve first uses the loop.
"""

import numba
import numpy as np

from mech._generated import one_equation as _abc
from mech._generated import rssr as _gen
from mech._scaling import DEAD_POINT_RTOL

__all__ = []

_jit = numba.njit(cache=True, error_model="numpy", inline="always")
_rssr_abc = _jit(_gen.rssr_abc)
_rssr_abc_rates = _jit(_gen.rssr_abc_rates)
_rssr_reach = _jit(_gen.rssr_reach)
_rssr_discriminant = _jit(_gen.rssr_discriminant)
_rssr_points = _jit(_gen.rssr_points)
_rssr_velocity = _jit(_gen.rssr_velocity)
_rssr_acceleration = _jit(_gen.rssr_acceleration)
_rssr_coupler_point = _jit(_gen.rssr_coupler_point)
_abc_discriminant = _jit(_abc.abc_discriminant)
_abc_solve = _jit(_abc.abc_solve)
_abc_rate = _jit(_abc.abc_rate)
_abc_accel = _jit(_abc.abc_accel)


@numba.njit(cache=True, error_model="numpy")
def _loop(dims, coupler, sigma, scale, order, phi01, omega, alpha, phi03, valid, dead, pts, rates, w3s, a3s):
    # `spoiled`: an assembled pose with a field that is not finite (overflow), for `Pose`'s check
    spoiled = False
    l1, l2, l3, s0, s3, h0, lam = dims[0], dims[1], dims[2], dims[3], dims[4], dims[5], dims[6]
    p, q, u = coupler[0], coupler[1], coupler[2]
    straight = q == 0.0 and u == 0.0
    ratio = p / l2
    for t in range(phi01.shape[0]):
        phi = phi01[t]
        A, B, C = _rssr_abc(l1, l2, l3, s0, s3, h0, lam, phi)
        _, rho, r2 = _rssr_reach(l1, l2, l3, s0, s3, h0, lam, phi)
        if r2 >= 0.0:
            disc = _rssr_discriminant(l1, l3, rho, np.sqrt(max(r2, 0.0)))
        else:
            disc = _abc_discriminant(A, B, C)
        isdead = abs(disc) <= DEAD_POINT_RTOL * (A * A + B * B + C * C)
        if isdead and disc < 0.0:
            disc = 0.0
        ok = disc >= 0.0
        root = np.sqrt(disc) if ok else 0.0
        psi = _abc_solve(A, B, C, root, sigma) if ok else np.nan
        phi03[t], valid[t], dead[t] = psi, ok, isdead
        Bx, By, Bz, Cx, Cy, Cz = _rssr_points(l1, l3, s0, s3, h0, lam, phi, psi)
        if straight:
            Px, Py, Pz = Bx + ratio * (Cx - Bx), By + ratio * (Cy - By), Bz + ratio * (Cz - Bz)
        else:
            Px, Py, Pz = _rssr_coupler_point(Bx, By, Bz, Cx, Cy, Cz, l2, lam, p, q, u)
        pts[0, t, 0], pts[0, t, 1], pts[0, t, 2] = Bx * scale, By * scale, Bz * scale
        pts[1, t, 0], pts[1, t, 1], pts[1, t, 2] = Cx * scale, Cy * scale, Cz * scale
        pts[2, t, 0], pts[2, t, 1], pts[2, t, 2] = Px * scale, Py * scale, Pz * scale
        if ok and not spoiled:
            for k in range(3):
                spoiled |= not (np.isfinite(pts[0, t, k]) and np.isfinite(pts[1, t, k]) and np.isfinite(pts[2, t, k]))
        if order >= 1:
            w = omega[t]
            a = alpha[t] if order >= 2 else 0.0
            dA, dB, dC, ddA, ddB, ddC = _rssr_abc_rates(l1, l2, l3, s0, s3, h0, lam, phi, w, a)
            w3 = _abc_rate(dA, dB, dC, psi, root, sigma) if ok and not isdead else np.nan
            w3s[t] = w3
            v0, v1, v2, v3, v4, v5 = _rssr_velocity(l1, l3, lam, phi, psi, w, w3)
            rates[0, t, 0], rates[0, t, 1], rates[0, t, 2] = v0 * scale, v1 * scale, v2 * scale
            if ok and not spoiled:      # the crank pin's rates are not masked: check them here
                spoiled |= not (np.isfinite(rates[0, t, 0]) and np.isfinite(rates[0, t, 1]))
            rates[1, t, 0], rates[1, t, 1], rates[1, t, 2] = v3 * scale, v4 * scale, v5 * scale
            if order >= 2:
                a3 = _abc_accel(C, dA, dB, ddA, ddB, ddC, psi, w3, root, sigma) if ok and not isdead else np.nan
                a3s[t] = a3
                c0, c1, c2, c3, c4, c5 = _rssr_acceleration(l1, l3, lam, phi, psi, w, w3, a, a3)
                rates[2, t, 0], rates[2, t, 1], rates[2, t, 2] = c0 * scale, c1 * scale, c2 * scale
                if ok and not spoiled:
                    spoiled |= not (np.isfinite(rates[2, t, 0]) and np.isfinite(rates[2, t, 1]))
                rates[3, t, 0], rates[3, t, 1], rates[3, t, 2] = c3 * scale, c4 * scale, c5 * scale
    return spoiled


def solve_fields(rssr, phi01, rates, order):
    """The fields of `RSSR._solve_fields` by the loop, before the masks of the rates.

    Points and linear rates are in the user's unit. Also returns True if an assembled pose
    has a position or a crank-pin rate that is not finite (a value beyond the float range):
    only then must `mech._pose.Pose` look for such values (the rocker's rates are checked by
    `mask_singular_rates`).
    """
    shape = phi01.shape
    n = phi01.size
    flat = np.ascontiguousarray(phi01, dtype=float).reshape(n)
    w = np.ascontiguousarray(np.broadcast_to(rates[0], shape), dtype=float).reshape(n) if order >= 1 else flat
    a = np.ascontiguousarray(np.broadcast_to(rates[1], shape), dtype=float).reshape(n) if order >= 2 else flat
    phi03, valid, dead = np.empty(n), np.empty(n, bool), np.empty(n, bool)
    pts = np.empty((3, n, 3))
    out_rates = np.empty((2 * order, n, 3))
    w3, a3 = np.empty(n if order >= 1 else 0), np.empty(n if order >= 2 else 0)
    spoiled = _loop(np.array(rssr._unit, dtype=float), np.array(rssr._unit_coupler, dtype=float), float(rssr._branch),
          float(rssr._scale), order, flat, w, a, phi03, valid, dead, pts, out_rates, w3, a3)
    vectors = shape + (3,)
    fields = {"phi01": phi01[()], "phi03": phi03.reshape(shape)[()], "valid": valid.reshape(shape)[()],
              "B": pts[0].reshape(vectors), "C": pts[1].reshape(vectors), "P": pts[2].reshape(vectors)}
    if order >= 1:
        fields["omega_output"] = w3.reshape(shape)[()]
        fields["vB"], fields["vC"] = out_rates[0].reshape(vectors), out_rates[1].reshape(vectors)
    if order >= 2:
        fields["alpha_output"] = a3.reshape(shape)[()]
        fields["aB"], fields["aC"] = out_rates[2].reshape(vectors), out_rates[3].reshape(vectors)
    return fields, spoiled
