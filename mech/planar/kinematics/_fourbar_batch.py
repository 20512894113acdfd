"""Many four-bars at once: positions of L linkages at their input angles in one call.

`FourBar.solve` serves one linkage; the atlas, path synthesis and the optimisers evaluate
thousands of candidates, each at the same few hundred angles. `solve_fourbars` takes
arrays of dimensions and gives every linkage the rules `FourBar` gives it (its own
power-of-two unit, assembly gaps zeroed within ``rtol``, the signed form at a change point)
with the same generated kernels: on NumPy the formulas of
``mech._generated.fourbar_position`` over blocks of linkages that fit in cache, on numba
one compiled loop over the linkages that calls the generated fused kernel of each. The
inputs within rounding of a dead point are then put on it, as `FourBar` puts them; the
linkages `FourBar` solves by other rules (kites, whose crank pin passes through D, and
lengths beyond 2**1000) are solved one by one by `FourBar` itself.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from mech import _backend
from mech._generated import fourbar_position as _gen
from mech._scaling import DEAD_POINT_RTOL
from mech._validate import finite_array, nonnegative_number
from mech.planar.kinematics._fourbar import _EXACT_EXPONENT, FourBar

__all__ = []        # internal for now: the atlas and the optimisers will call it; not re-exported

_LOOP = {}


class FourBarBatch(NamedTuple):
    """Positions of many four-bars, each array of shape (linkages, angles)."""

    B: np.ndarray         # crank pin
    C: np.ndarray         # rocker pin
    P: np.ndarray         # coupler point
    valid: np.ndarray     # where the linkage assembles


def _column(name, value, n):
    x = finite_array(name, value)
    if x.ndim > 1 or (x.ndim == 1 and x.shape[0] not in (1, n)):
        raise ValueError(f"Expected `{name}` one number or an array of shape ({n},), got shape {x.shape}")
    return np.ascontiguousarray(np.broadcast_to(x, (n,)), dtype=float)


def solve_fourbars(a, b, c, d, theta, *, coupler=(0.0, 0.0), branch=1, rtol=1e-12):
    """Positions of L four-bars at their input angles, in one call.

    Parameters
    ----------
    a, b, c, d : array_like, shape (L,) or one number
        Crank, coupler, rocker and ground of each linkage (any unit, as `FourBar`).
    theta : array_like, shape (K,) or (L, K)
        Crank angles, radians: the same K for every linkage, or K per linkage.
    coupler : (array_like, array_like), optional
        Coupler point ``(p, q)`` of each linkage, in `FourBar`'s convention.
    branch : array_like of +1 and -1, optional
        Assembly branch of each linkage.
    rtol : float, optional
        Change-point tolerance, as `FourBar`'s.

    Returns
    -------
    FourBarBatch
        ``B, C, P`` (complex) and ``valid``, shape (L, K): row i is
        ``FourBar(a[i], b[i], c[i], d[i], branch=branch[i], coupler=(p[i], q[i])).solve(theta_i)``
        (eqs. 2-11, 2-12 by ``fourbar_position``), to the bit on numba and within a few
        units in the last place on NumPy (`tests/test_fourbar_batch.py`).

    Raises
    ------
    ValueError
        For a length that is not positive and finite or not shorter than the other three
        together (naming the linkage), a branch other than +1 or -1, or shapes that differ.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.kinematics._fourbar_batch import solve_fourbars
    >>> out = solve_fourbars([10, 20], 40, 30, 35, np.linspace(0, 1, 5))
    >>> out.C.shape, bool(out.valid.all())
    ((2, 5), True)
    """
    th = finite_array("theta", theta)
    if th.ndim not in (1, 2):
        raise ValueError(f"Expected `theta` of shape (K,) or (L, K), got shape {th.shape}")
    sizes = [np.size(x) for x in (a, b, c, d, *coupler, branch)] + ([th.shape[0]] if th.ndim == 2 else [])
    n = max(sizes)
    a, b, c, d = (_column(k, v, n) for k, v in zip("abcd", (a, b, c, d)))
    p, q = (_column(f"coupler[{k}]", v, n) for k, v in enumerate(coupler))
    br = _column("branch", branch, n)
    if not np.all(np.abs(br) == 1.0):
        raise ValueError(f"Expected `branch` +1 or -1, got {br[np.abs(br) != 1.0][0]!r}")
    if th.ndim == 2 and th.shape[0] not in (1, n):
        raise ValueError(f"Expected `theta` of shape ({n}, K), got shape {th.shape}")
    rtol = nonnegative_number("rtol", rtol)
    k = th.shape[-1]
    lengths = np.stack([a, b, c, d])
    bad = ~(lengths > 0.0)
    if bad.any():
        j, i = np.argwhere(bad)[0]
        raise ValueError(f"Expected `{'abcd'[j]}` > 0, got {lengths[j, i]!r} for linkage {i}")
    # each linkage in the power of two that puts its longest link in [1/2, 1), as `fourbar_lengths`
    exponent = np.frexp(lengths.max(axis=0))[1]
    unit = np.ldexp(lengths, -exponent)
    total = unit.sum(axis=0)
    bad = unit >= total - unit
    if bad.any():
        j, i = np.argwhere(bad)[0]
        raise ValueError(f"Expected `{'abcd'[j]}` shorter than the other three links together, got "
                         f"{lengths[j, i]!r} for linkage {i}")
    ua, ub, uc, ud = unit
    gaps = np.array(_gen.fourbar_assembly_gaps(ua, ub, uc, ud))
    gaps[np.abs(gaps) <= rtol * total] = 0.0                # as `assembly_gaps`
    zero = gaps == 0.0
    m23 = (zero[0] | zero[1]).astype(float)
    m4 = zero[2].astype(float)
    kite = zero[0] & zero[1]
    tol = 2.0 * DEAD_POINT_RTOL * total                     # as `FourBar._may_meet_dead_point`
    close = np.where(uc > ub, gaps[0], gaps[1])
    dead = ((gaps[2] != 0.0) & (gaps[2] <= tol)) | ((close != 0.0) & (close <= tol))
    other = kite | (exponent < 0) | (exponent > _EXACT_EXPONENT) | (ub < 2.0**-1022)
    up, uq = np.ldexp(p, -exponent), np.ldexp(q, -exponent)
    scale = np.ldexp(1.0, exponent)
    out = np.empty((3, n, k), dtype=complex)
    valid = np.empty((n, k), dtype=bool)
    thetas = np.ascontiguousarray(th.reshape(-1, k))        # (1, K) or (L, K)
    columns = (ua, ub, uc, ud, up, uq, br, *gaps, m23, m4, scale)
    if _backend.use_numba(n * k):
        _loop()(*columns, thetas, out, valid)
    else:
        _numpy(columns, thetas, out, valid)
    snap = np.flatnonzero(dead & ~other)
    if snap.size:
        _snap_dead_points(snap, (ua, ub, uc, ud, up, uq, scale), gaps, close, thetas, out, valid,
                          _backend.use_numba(n * k))
    for i in np.flatnonzero(other):
        pose = FourBar(a[i], b[i], c[i], d[i], branch=int(br[i]), coupler=(p[i], q[i])).solve(
            thetas[i if thetas.shape[0] > 1 else 0])
        out[0, i], out[1, i], out[2, i], valid[i] = pose.B, pose.C, pose.P, pose.valid
    return FourBarBatch(out[0], out[1], out[2], valid)


def _snap_dead_points(rows, columns, gaps, close, theta, out, valid, compiled=False):
    """`FourBar._dead_points` at order 0 for the linkages `rows`: an input within
    `DEAD_POINT_RTOL` of a dead point that did not assemble is the dead point (C on BD).

    A linkage that does not turn fully has a dead point, and about half of its poses do not
    assemble: checking each of them in NumPy cost more than the solve. With `compiled`, a
    numba loop first keeps the poses within four times the tolerance (numba's sine may differ
    from NumPy's in the last bit, far inside that margin), and NumPy decides on those.
    """
    if compiled:
        ua, ub, uc, ud = columns[:4]
        keep = np.zeros((rows.size, valid.shape[1]), dtype=bool)
        _near()(rows, ua, ub, uc, ud, gaps[2], close, theta, valid, 4.0 * DEAD_POINT_RTOL, keep)
        i, j = np.nonzero(keep)
    else:
        i, j = np.nonzero(~valid[rows])            # only a pose that did not assemble is snapped
    if not i.size:
        return
    ua, ub, uc, ud, up, uq, scale = (x[rows][i] for x in columns)
    t = theta[rows[i], j] if theta.shape[0] > 1 else theta[0, j]
    tol = DEAD_POINT_RTOL * (ua + ub + uc + ud)
    s = np.sin(0.5 * t)
    k = np.sqrt((ud - ua) ** 2 + 4.0 * ua * ud * s * s)          # |BD|, as `dead_points_near`
    near_far = (np.abs(k - (ub + uc)) <= tol) & (gaps[2][rows][i] != 0.0)
    near_close = (np.abs(np.abs(ub - uc) - k) <= tol) & (close[rows][i] != 0.0)
    hit = near_far | near_close
    if not hit.any():
        return
    a, b, c, d, p, q, sc, t, k, far = (x[hit] for x in (ua, ub, uc, ud, up, uq, scale, t, k, near_far))
    B = a * np.exp(1j * t)
    sign = np.where(far | (b >= c), 1.0, -1.0)
    C = B + sign * b * (d - B) / k
    P = B + (p + 1j * q) * (C - B) / b
    r, j = rows[i[hit]], j[hit]
    for n, z in enumerate((B, C, P)):
        out[n, r, j] = (z.real * sc) + 1j * (z.imag * sc)           # each part times 2**e, as `FourBar.solve`
    valid[r, j] = True


def _numpy(columns, theta, out, valid):
    """The NumPy backend: the generated formulas over blocks of whole linkages."""
    ua, ub, uc, ud, up, uq, br, g2, g3, g4, m23, m4, scale = columns
    n, k = out.shape[1:]
    rows = max(1, _backend.BLOCK // max(k, 1))
    signed = (m23 + m4) > 0
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for start in range(0, n, rows):
            part = slice(start, min(start + rows, n))
            th = theta[part] if theta.shape[0] > 1 else theta
            for pick in (~signed[part], signed[part]):
                if not pick.any():
                    continue
                idx = np.arange(part.start, part.stop)[pick]
                col = lambda x: x[idx, None]        # noqa: E731
                t = th[pick] if th.shape[0] > 1 else th
                args = (col(ua), col(ub), col(uc), col(ud), col(up), col(uq), t, col(br), col(g2), col(g3), col(g4))
                if signed[idx[0]]:
                    bx, by, cx, cy, px, py, S = _gen.fourbar_position_signed(*args, col(m23), col(m4))
                else:
                    bx, by, cx, cy, px, py, S = _gen.fourbar_position(*args)
                s = col(scale)
                for j, (x, y) in enumerate(((bx, by), (cx, cy), (px, py))):
                    z = np.empty(np.broadcast_shapes(np.shape(x), (idx.size, k)), dtype=complex)
                    z.real, z.imag = x * s, y * s
                    out[j, idx] = z
                valid[idx] = S == S


def _loop():
    """The numba backend: one compiled loop over the linkages, each by the generated fused kernel."""
    fn = _LOOP.get("loop")
    if fn is None:
        import numba

        kernels = _backend.numba_kernels("fourbar_position")
        plain, signed = kernels.fourbar_position_fused_kernel, kernels.fourbar_position_signed_fused_kernel

        @numba.njit(cache=True, nogil=True, error_model="numpy")
        def loop(ua, ub, uc, ud, up, uq, br, g2, g3, g4, m23, m4, scale, theta, out, valid):
            k = out.shape[2]
            scales = np.empty(7)
            S = np.empty(k)
            for i in range(ua.shape[0]):
                th = theta[i] if theta.shape[0] > 1 else theta[0]
                for j in range(6):
                    scales[j] = scale[i]
                scales[6] = 1.0
                B, C, P = out[0, i], out[1, i], out[2, i]
                if m23[i] + m4[i] > 0.0:
                    signed(ua[i], ub[i], uc[i], ud[i], up[i], uq[i], th, br[i], g2[i], g3[i], g4[i], m23[i], m4[i],
                           scales, B.real, B.imag, C.real, C.imag, P.real, P.imag, S, valid[i])
                else:
                    plain(ua[i], ub[i], uc[i], ud[i], up[i], uq[i], th, br[i], g2[i], g3[i], g4[i],
                          scales, B.real, B.imag, C.real, C.imag, P.real, P.imag, S, valid[i])

        fn = _LOOP["loop"] = loop
    return fn



def _near():
    """The compiled pre-check of `_snap_dead_points`: poses near a dead point, generously."""
    fn = _LOOP.get("near")
    if fn is None:
        import math

        import numba

        @numba.njit(cache=True, nogil=True, error_model="numpy")
        def near(rows, ua, ub, uc, ud, gap, close, theta, valid, rtol, keep):
            for r in range(rows.shape[0]):
                i = rows[r]
                th = theta[i] if theta.shape[0] > 1 else theta[0]
                tol = rtol * (ua[i] + ub[i] + uc[i] + ud[i])
                far, short = ub[i] + uc[i], abs(ub[i] - uc[i])
                for j in range(valid.shape[1]):
                    if valid[i, j]:
                        continue
                    s = math.sin(0.5 * th[j])
                    k = math.sqrt((ud[i] - ua[i]) ** 2 + 4.0 * ua[i] * ud[i] * s * s)
                    keep[r, j] = ((abs(k - far) <= tol and gap[i] != 0.0)
                                  or (abs(short - k) <= tol and close[i] != 0.0))

        fn = _LOOP["near"] = near
    return fn
