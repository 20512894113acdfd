"""`OpenChain.solve` as one compiled loop over the poses (the numba backend).

Pose by pose, the loop multiplies the H-D matrices of (2-67) from a numba-compiled copy of
the generated ``hd_entries`` (``mech._generated.transforms``) and propagates the rates of
(2-74) in the order of the NumPy path (`OpenChain._solve_fields`): the same sums, products
and cross products in the same order. The 4 x 4 products are written out as sums over
k = 0..3 (NumPy's own loop); NumPy may hand a stack of products to BLAS, whose fused
multiply-adds round differently, and ``sin``, ``cos`` come from libm instead of NumPy, so
the two paths agree within a few ulp, not always bit for bit: the tests allow 4 ulp per
joint of each field's largest magnitude (2.2 ulp measured on a five-joint chain at order 2).

This module imports numba: it is imported only when a solve first uses the loop.
"""

import numba
import numpy as np

from mech._generated import transforms as _gen

__all__ = []

_hd = numba.njit(cache=True, error_model="numpy", inline="always")(_gen.hd_entries)


@numba.njit(cache=True, error_model="numpy", inline="always")
def _cross(a0, a1, a2, b0, b1, b2):
    return a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0


@numba.njit(cache=True, error_model="numpy", inline="always")
def _var(base, w, col, x, t):
    # the NumPy path adds the weighted variable to a sum that starts at 0
    return base if col < 0 else base + (0.0 + w * x[t, col])


@numba.njit(cache=True, error_model="numpy")
def _loop(par, cols, order, q, qd, qdd, point, M, P, R):
    J = par.shape[0]
    px, py, pz = point[0], point[1], point[2]
    T = np.empty((3, 4))
    N = np.empty((3, 4))
    for t in range(q.shape[0]):
        T[:] = 0.0
        T[0, 0] = T[1, 1] = T[2, 2] = 1.0
        wx = wy = wz = vx = vy = vz = ax = ay = az = ex = ey = ez = 0.0
        for k in range(J):
            phi = _var(par[k, 0], par[k, 4], cols[k, 0], q, t)
            s = _var(par[k, 2], par[k, 5], cols[k, 1], q, t)
            zx, zy, zz = T[0, 2], T[1, 2], T[2, 2]
            ox, oy, oz = T[0, 3], T[1, 3], T[2, 3]
            m00, m01, m02, m03, m10, m11, m12, m13, m20, m21, m22, m23 = _hd(phi, par[k, 1], s, par[k, 3])
            for i in range(3):
                t0, t1, t2, t3 = T[i, 0], T[i, 1], T[i, 2], T[i, 3]
                # row 3 of an H-D matrix is (0, 0, 0, 1), summed last as NumPy's product does
                N[i, 0] = t0 * m00 + t1 * m10 + t2 * m20 + t3 * 0.0
                N[i, 1] = t0 * m01 + t1 * m11 + t2 * m21 + t3 * 0.0
                N[i, 2] = t0 * m02 + t1 * m12 + t2 * m22 + t3 * 0.0
                N[i, 3] = t0 * m03 + t1 * m13 + t2 * m23 + t3 * 1.0
            T[:] = N
            rx, ry, rz = T[0, 3] - ox, T[1, 3] - oy, T[2, 3] - oz
            if order >= 1:
                dphi = _var(0.0, par[k, 4], cols[k, 0], qd, t) if cols[k, 0] >= 0 else 0.0
                ds = _var(0.0, par[k, 5], cols[k, 1], qd, t) if cols[k, 1] >= 0 else 0.0
                nwx, nwy, nwz = wx + dphi * zx, wy + dphi * zy, wz + dphi * zz
                cx, cy, cz = _cross(nwx, nwy, nwz, rx, ry, rz)
                nvx, nvy, nvz = vx + cx + ds * zx, vy + cy + ds * zy, vz + cz + ds * zz
            if order >= 2:
                ddphi = _var(0.0, par[k, 4], cols[k, 0], qdd, t) if cols[k, 0] >= 0 else 0.0
                dds = _var(0.0, par[k, 5], cols[k, 1], qdd, t) if cols[k, 1] >= 0 else 0.0
                dzx, dzy, dzz = _cross(wx, wy, wz, zx, zy, zz)
                ex, ey, ez = ex + ddphi * zx + dphi * dzx, ey + ddphi * zy + dphi * dzy, ez + ddphi * zz + dphi * dzz
                c1x, c1y, c1z = _cross(ex, ey, ez, rx, ry, rz)
                c2x, c2y, c2z = _cross(nwx, nwy, nwz, nvx - vx, nvy - vy, nvz - vz)
                ax = ax + c1x + c2x + dds * zx + ds * dzx
                ay = ay + c1y + c2y + dds * zy + ds * dzy
                az = az + c1z + c2z + dds * zz + ds * dzz
            if order >= 1:
                wx, wy, wz, vx, vy, vz = nwx, nwy, nwz, nvx, nvy, nvz
        for i in range(3):
            for j in range(4):
                M[t, i, j] = T[i, j]
        M[t, 3, 0] = M[t, 3, 1] = M[t, 3, 2] = 0.0
        M[t, 3, 3] = 1.0
        dx = T[0, 0] * px + T[0, 1] * py + T[0, 2] * pz
        dy = T[1, 0] * px + T[1, 1] * py + T[1, 2] * pz
        dz = T[2, 0] * px + T[2, 1] * py + T[2, 2] * pz
        P[t, 0], P[t, 1], P[t, 2] = T[0, 3] + dx, T[1, 3] + dy, T[2, 3] + dz
        if order >= 1:
            cx, cy, cz = _cross(wx, wy, wz, dx, dy, dz)
            R[0, t, 0], R[0, t, 1], R[0, t, 2] = vx + cx, vy + cy, vz + cz
            R[1, t, 0], R[1, t, 1], R[1, t, 2] = wx, wy, wz
        if order >= 2:
            cx, cy, cz = _cross(ex, ey, ez, dx, dy, dz)
            fx, fy, fz = _cross(wx, wy, wz, dx, dy, dz)
            gx, gy, gz = _cross(wx, wy, wz, fx, fy, fz)
            R[2, t, 0], R[2, t, 1], R[2, t, 2] = ax + cx + gx, ay + cy + gy, az + cz + gz
            R[3, t, 0], R[3, t, 1], R[3, t, 2] = ex, ey, ez


def _tables(chain):
    """Per joint: (phi, lam, s, h, dphi/dq, ds/dq) and the columns of q read (-1: none)."""
    par, cols, k = np.zeros((len(chain.joints), 6)), np.full((len(chain.joints), 2), -1, np.int64), 0
    for i, joint in enumerate(chain.joints):
        w_phi, w_s = joint.weights
        par[i, :4] = joint.phi, joint.lam, joint.s, joint.h
        for c in range(joint.dof):
            if w_phi[c] != 0.0:
                cols[i, 0], par[i, 4] = k + c, w_phi[c]
            if w_s[c] != 0.0:
                cols[i, 1], par[i, 5] = k + c, w_s[c]
        k += joint.dof
    return par, cols


def solve_fields(chain, q, qd, qdd, order, point, shape):
    """The fields of `OpenChain.solve` for joint values broadcast to ``shape + (dof,)``."""
    tables = chain.__dict__.get("_compiled_tables")
    if tables is None:
        tables = chain._compiled_tables = _tables(chain)
    n = int(np.prod(shape, dtype=np.int64))

    def flat(x):
        return np.ascontiguousarray(x, dtype=float).reshape(n, chain.dof)

    qf = flat(q)
    qdf = flat(qd) if order >= 1 else qf
    qddf = flat(qdd) if order >= 2 else qf
    M, P = np.empty((n, 4, 4)), np.empty((n, 3))
    R = np.empty((2 * order, n, 3))
    _loop(tables[0], tables[1], order, qf, qdf, qddf, np.ascontiguousarray(point, dtype=float), M, P, R)
    M = M.reshape(shape + (4, 4))
    fields = {"M": M, "P": P.reshape(shape + (3,)),
              "e1": M[..., :3, 0], "e2": M[..., :3, 1], "e3": M[..., :3, 2]}
    names = ("vP", "omega", "aP", "alpha")[: 2 * order]
    for i, name in enumerate(names):
        fields[name] = R[i].reshape(shape + (3,))
    return fields
