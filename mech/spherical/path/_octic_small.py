"""The coupler octic of a small spherical four-bar without cancellation (eqs. (7)-(9) of
``derivations/spherical/coupler_curve_small.md``).

For arcs of order eps the octic F is of order eps**12 near the linkage and the direct
evaluation (``mech._generated.spherical_coupler_curve``) loses about 1/eps**2 of its relative
accuracy. Here the point is written in the linkage's own frame, centred at the input pivot
A and scaled by the size eps, and the generated factors G+ and G- carry the powers of eps
divided out symbolically: F = eps**12 G+ G- (eq. (9)).
"""

import numpy as np

from mech._generated import spherical_coupler_small as _small

__all__ = ["frames", "linkage_size", "octic_small"]


def frames(params):
    """Placement rotations ``ground_frame(lon, lat, heading)`` for arrays of nine
    parameters, shape (..., 9) -> (..., 3, 3) (columns: the direction of A->D at A, the
    direction 90 degrees counter-clockwise from it, A)."""
    lon, lat, heading = params[..., 0], params[..., 1], params[..., 2]
    cl, sl, co, so = np.cos(lat), np.sin(lat), np.cos(lon), np.sin(lon)
    ch, sh = np.cos(heading), np.sin(heading)
    x = np.stack([sl * co, sl * so, -cl], axis=-1)
    y = np.stack([-so, co, np.zeros_like(so)], axis=-1)
    A = np.stack([cl * co, cl * so, sl], axis=-1)
    return np.stack([ch[..., None] * x + sh[..., None] * y, -sh[..., None] * x + ch[..., None] * y, A], axis=-1)


def linkage_size(params):
    """The size eps of a linkage: its largest arc among a, b, c, d and r, shape (...)."""
    return np.max(params[..., 3:8], axis=-1)


def octic_small(params, frame, u, *, block=1 << 14):
    """F and its gradient at unit vectors `u` by the scaled form, eqs. (7)-(9).

    Parameters
    ----------
    params : ndarray, shape (n, 9) or (9,)
        Validated nine parameters, one row per point, or one linkage for all.
    frame : ndarray, shape (n, 3, 3) or (3, 3)
        The placement rotation of each row (its last column is A), or one for all.
    u : ndarray, shape (n, 3)
        Unit vectors, on the side of A (``u . A > -1``).
    block : int
        Points per call of the generated code.

    Returns
    -------
    value : ndarray, shape (n,)
    gradient : ndarray, shape (n, 3)
        F and dF/dx at the unit vectors; the caller scales them by |x|**8 and |x|**7.
    """
    one = params.ndim == 1
    eps = linkage_size(params)
    hats = params[..., 3:8] / np.asarray(eps)[..., None]
    A = frame[..., :, 2]
    # the point in the standard frame, centred at A: u_std = e_z + R^T (u - A)
    rel = np.einsum("ji,nj->ni", frame, u - A) if one else np.einsum("nji,nj->ni", frame, u - A)
    one_plus_z = 2.0 + rel[:, 2]
    X = 2.0 * rel[:, 0] / (one_plus_z * eps)
    Y = 2.0 * rel[:, 1] / (one_plus_z * eps)
    out = np.empty((6, X.shape[0]))
    for s in range(0, X.shape[0], block):
        blk = slice(s, s + block)
        args = (eps, *hats, params[8]) if one else (eps[blk], *hats[blk].T, params[blk, 8])
        out[:, blk] = np.broadcast_arrays(*_small.spherical_coupler_octic_small(X[blk], Y[blk], *args))
    Gp, Gp_X, Gp_Y, Gm, Gm_X, Gm_Y = out
    phi = Gp * Gm
    phi_X = Gp_X * Gm + Gp * Gm_X
    phi_Y = Gp_Y * Gm + Gp * Gm_Y
    rho = 1.0 + 0.25 * eps**2 * (X**2 + Y**2)
    # F at x_h = (eps X, eps Y, 1 - eps^2 (X^2 + Y^2) / 4), of length rho (eq. (7)), and its
    # gradient there from d/dX, d/dY and Euler's relation x . grad F = 8 F
    e11 = eps**11
    g3 = e11 * eps * (8.0 * phi - X * phi_X - Y * phi_Y) / rho
    g1 = e11 * phi_X + 0.5 * eps * X * g3
    g2 = e11 * phi_Y + 0.5 * eps * Y * g3
    # u = x_h / rho: F(u) = F(x_h) / rho**8, grad F(u) = grad F(x_h) / rho**7
    value = e11 * eps * phi / rho**8
    grad_std = np.stack([g1, g2, g3], axis=-1) / (rho**7)[:, None]
    return value, (np.einsum("ij,nj->ni", frame, grad_std) if one else np.einsum("nij,nj->ni", frame, grad_std))
