"""The implicit coupler curves of the spherical six-bars (monograph §2.2, §2.7 to §2.9).

The coupler point P of `stephenson1`, `stephenson2`, `watt1` and `watt2` rides on the link
EG. Given P and E, G is a fixed combination of P, E and P x E, so P is on the curve when
three equations in two angles of the first loop share a root: the closure L of the
four-bar, E . P = cos r and G . F = cos f. Their resultant is the curve. It is never
expanded: the trigonometric coefficients of the three equations are built numerically
(here), then Cramer's condition or the 8 x 8 Dixon matrix (generated code) is evaluated.
Formulas: ``mech._generated.spherical_sixbar_curves``, derived in
``derivations/spherical/sixbar_curves.md``.
"""

import numpy as np

from mech._generated import spherical_sixbar_curves as _gen
from mech._geometry import unit_rows
from mech._validate import bool_flag, finite_array

__all__ = ["SIXBAR_CURVE_ORDERS", "sixbar_curve"]

#: Order of each six-bar's coupler curve (degree of the cone over it), proved in the derivation.
SIXBAR_CURVE_ORDERS = {"stephenson1": 24, "stephenson2": 32, "watt1": 24, "watt2": 8}
_CARRIERS = {("AB", "DC"): "stephenson1", ("BC", None): "stephenson2", ("BC", "DC"): "watt1",
             ("DC", None): "watt2"}
_BLOCK = 2048
# Fourier coefficients (e^{-ix}, 1, e^{ix}) -> coefficients of (1, cos x, sin x) -> of (1, t, t^2),
# t = tan(x/2), for (1 + t^2) times the trigonometric polynomial
_F2T = np.array([[1, 1, 0], [0, 0, 2], [1, -1, 0]]) @ np.array([[0, 1, 0], [1, 0, 1], [-1j, 0, 1j]])


def _toward(o, x, r, g=0.0):
    """The point at arc r from o, at the angle g from the great circle o -> x (eq. (1) of the solver)."""
    T = unit_rows(x - (o @ x) * o)
    return np.cos(r) * o + np.sin(r) * (np.cos(g) * T + np.sin(g) * np.cross(o, T))


# ----------------------------------------------------------------------------- trigonometric polynomials
# A scalar is an array (5, 5) of Fourier coefficients: entry [m + 2, n + 2] multiplies
# e^{i(m theta + n psi)}; a vector is an array (3, 5, 5).
def _const(v):
    v = np.asarray(v, dtype=float)
    out = np.zeros(v.shape + (5, 5), dtype=complex)
    out[..., 2, 2] = v
    return out


def _mul(a, b):
    """Product of two scalars of degree <= 1 in each angle."""
    out = np.zeros(np.broadcast_shapes(a.shape, b.shape), dtype=complex)
    for m1 in range(1, 4):
        for n1 in range(1, 4):
            for m2 in range(1, 4):
                for n2 in range(1, 4):
                    out[..., m1 + m2 - 2, n1 + n2 - 2] += a[..., m1, n1] * b[..., m2, n2]
    return out


def _poly_dot(a, b):
    """Dot product of 3-vectors whose components are polynomials multiplied by `_mul`."""
    return sum(_mul(a[k], b[k]) for k in range(3))


def _poly_cross(a, b):
    """Cross product of 3-vectors whose components are polynomials multiplied by `_mul`."""
    return np.stack([_mul(a[1], b[2]) - _mul(a[2], b[1]), _mul(a[2], b[0]) - _mul(a[0], b[2]),
                     _mul(a[0], b[1]) - _mul(a[1], b[0])])


def _rotate(axis, angle, p):
    """R_axis(x) p for the angle x = theta (angle=0) or psi (angle=1); `axis` a fixed unit vector."""
    ax = 1 if angle == 0 else 2
    along = np.einsum("k,k...->...", axis, p)
    par = axis[:, None, None] * along
    perp = p - par
    turn = np.cross(axis, perp, axisa=0, axisb=0, axisc=0)
    up, down = np.roll(perp, 1, axis=ax), np.roll(perp, -1, axis=ax)
    tup, tdown = np.roll(turn, 1, axis=ax), np.roll(turn, -1, axis=ax)
    return par + (up + down) / 2 + (tup - tdown) / 2j


# ----------------------------------------------------------------------------- the linkage
def _geometry(linkage):
    """The kind and the point-free parts of eq. (2): L, E, F, E . F, E x F and the constants."""
    from mech.spherical.linkage._linkage import SphericalLinkage

    if not isinstance(linkage, SphericalLinkage):
        raise ValueError(f"Expected `linkage` to be a six-bar from stephenson1, stephenson2, watt1 or watt2, "
                         f"got {linkage!r}")
    steps = linkage._steps
    kinds = [s[0] for s in steps]
    points = {s[1]: s for s in steps if s[0] == "point"}
    grounds = {s[1]: np.asarray(s[2], dtype=float) for s in steps if s[0] == "ground"}
    dyads = [s for s in steps if s[0] == "rrr"]
    shape_ok = (kinds.count("crank") == 1 and len(dyads) == 2 and set(points) >= {"E", "P"}
                and {"A", "D"} <= set(grounds) and dyads[0][1] == ("BC", "DC") and dyads[0][2] == ("B", "D")
                and dyads[1][1] == ("EG", "FG") and dyads[1][2] == ("E", "F") and points["P"][2] == "EG")
    key = (points["E"][2], points["F"][2] if "F" in points else None) if shape_ok else None
    if key not in _CARRIERS or ("F" not in points and "F" not in grounds):
        raise ValueError(f"Expected `linkage` to be a six-bar from stephenson1, stephenson2, watt1 or watt2, "
                         f"got {linkage!r}")
    kind = _CARRIERS[key]
    crank = [s for s in steps if s[0] == "crank"][0]
    A, D = grounds["A"], grounds["D"]
    a, (b, c), (e, f) = crank[4], dyads[0][4], dyads[1][4]
    rE, gE = points["E"][3:5]
    r, g = points["P"][3:5]
    C0 = _toward(D, A, c)
    if kind == "watt1":                  # angles: mu (coupler about C0) and psi (rocker about D)
        B0 = _toward(C0, D, b)
        E0 = _toward(B0, C0, rE, gE)
        F0 = _toward(D, C0, *points["F"][3:5])
        E_mu = _rotate(C0, 0, _const(E0))
        E = _rotate(D, 1, E_mu)
        F = _rotate(D, 1, _const(F0))
        L = np.einsum("k,k...->...", A, _rotate(D, 1, _rotate(C0, 0, _const(B0)))) - np.cos(a) * _const(1.0)
        EF = np.einsum("k,k...->...", F0, E_mu)
    else:                                # angles: theta (crank about A) and psi (rocker about D)
        B0 = _toward(A, D, a)
        B = _rotate(A, 0, _const(B0))
        C = _rotate(D, 1, _const(C0))
        L = _poly_dot(B, C) - np.cos(b) * _const(1.0)
        if kind == "stephenson1":
            E = _rotate(A, 0, _const(_toward(A, B0, rE, gE)))
        elif kind == "watt2":
            E = _rotate(D, 1, _const(_toward(D, C0, rE, gE)))
        else:                            # E on the coupler: a fixed combination of B, C, B x C
            k = np.array([np.cos(rE) - np.sin(rE) * np.cos(gE) * np.cos(b) / np.sin(b),
                          np.sin(rE) * np.cos(gE) / np.sin(b), np.sin(rE) * np.sin(gE) / np.sin(b)])
            E = k[0] * B + k[1] * C + k[2] * _poly_cross(B, C)
        if kind == "stephenson1":
            F = _rotate(D, 1, _const(_toward(D, C0, *points["F"][3:5])))
        else:
            F = _const(grounds["F"]).reshape(3, 5, 5)
        EF = _poly_dot(E, F)
    # eq. (1): G = k1 P + k2 E + k3 P x E, so G . F = k1 P . F + k2 E . F + k3 P . (E x F)
    k1 = np.sin(e) * np.cos(g) / np.sin(r)
    k2 = (np.sin(r) * np.cos(e) - np.sin(e) * np.cos(g) * np.cos(r)) / np.sin(r)
    k3 = np.sin(e) * np.sin(g) / np.sin(r)
    ExF = _poly_cross(E, F)
    for name, part in (("L", L), ("E", E), ("EF", EF), ("ExF", ExF), ("F", F)):
        # bilinear: no harmonic beyond the first survives (E x F for Watt-1 to rounding)
        part[..., [0, 4], :] = 0.0
        part[..., :, [0, 4]] = 0.0
    return dict(kind=kind, L=L, E=E, F=F, EF=EF, ExF=ExF, k=(k1, k2, k3), cos_r=np.cos(r), cos_f=np.cos(f), D=D)


def _equations(geo, P):
    """g1 and g2 of eq. (2) at the points P (n, 3): Fourier arrays (n, 5, 5)."""
    k1, k2, k3 = geo["k"]
    one = _const(np.ones(P.shape[0]))
    g1 = np.einsum("nk,k...->n...", P, geo["E"]) - geo["cos_r"] * one
    g2 = (k1 * np.einsum("nk,k...->n...", P, geo["F"]) + k2 * geo["EF"]
          + k3 * np.einsum("nk,k...->n...", P, geo["ExF"]) - geo["cos_f"] * one)
    return g1, g2


def _psi_parts(f):
    """(A, B, C) with f = A cos psi + B sin psi + C; each a Fourier series in theta (..., 5)."""
    return f[..., :, 3] + f[..., :, 1], 1j * (f[..., :, 3] - f[..., :, 1]), f[..., :, 2]


def _at(series, z):
    """A Fourier series in theta (..., 5) at e^{i theta} = z."""
    return sum(series[..., m + 2] * z**m for m in range(-2, 3))


def _stephenson1(geo, P):
    g1, g2 = _equations(geo, P)
    L = np.broadcast_to(geo["L"], g2.shape)
    # g1 = a1 cos theta + b1 sin theta + c1 (E rides on the crank: no psi)
    a1, b1, c1 = (v.real for v in _psi_parts(np.swapaxes(g1, -1, -2))[:3])
    a1, b1, c1 = a1[..., 2], b1[..., 2], c1[..., 2]
    n2 = a1**2 + b1**2
    parts = _psi_parts(L) + _psi_parts(g2)
    # P along the crank axis (n2 -> 0): one root theta goes to infinity and the product
    # tends to (2 c1)**8 R_4 R_-4, R's extreme Fourier coefficients (those of the parts)
    limit = (n2 <= 1e-24 * c1**2)
    n2_safe = np.where(limit, 1.0, n2)
    s = np.sqrt((n2_safe - c1**2).astype(complex))
    value = n2_safe.astype(complex) ** 4
    # the roots z = e^{i theta} of g1: the larger one by the formula, the other from their
    # product (a1 + i b1) / (a1 - i b1), without cancellation
    z1, z2 = (((-a1 * c1 - sign * b1 * s) + 1j * (-b1 * c1 + sign * a1 * s)) / n2_safe for sign in (1.0, -1.0))
    big = np.where(limit, 1.0, np.where(np.abs(z1) >= np.abs(z2), z1, z2))
    product = np.where(limit, 1.0, a1 + 1j * b1) / np.where(limit, 1.0, a1 - 1j * b1)
    for z in (big, product / big):
        value = value * _gen.sixbar_cramer(*(_at(p, z) for p in parts))
    extreme = (2 * c1) ** 8 * (_gen.sixbar_cramer(*(p[..., 3] for p in parts))
                               * _gen.sixbar_cramer(*(p[..., 1] for p in parts)))
    return np.where(limit, extreme.real, value.real)


def _watt2(geo, P):
    g1, g2 = _equations(geo, P)
    parts = [p[..., 2] for p in _psi_parts(g1) + _psi_parts(g2)]      # no theta
    return _gen.sixbar_cramer(*parts).real


def _dixon(geo, P):
    g1, g2 = _equations(geo, P)
    L = np.broadcast_to(geo["L"], g1.shape)
    coefs = [np.einsum("im,...mn,jn->...ij", _F2T, f[..., 1:4, 1:4], _F2T).real for f in (L, g1, g2)]
    args = [c[..., i, j] for c in coefs for i in range(3) for j in range(3)]
    entries = _gen.sixbar_dixon(*args)
    M = np.stack([np.broadcast_to(x, P.shape[:1]) for x in entries], axis=-1).reshape(-1, 8, 8)
    value = np.linalg.det(M)
    if geo["kind"] == "watt1":           # the fixed pivot's factor |P x D|^4 (derivation, "Extraneous factors")
        pivot = np.sum(np.cross(P, geo["D"]) ** 2, axis=-1) ** 2
        at_pivot = pivot == 0.0
        value = value / np.where(at_pivot, 1.0, pivot)
        if np.any(at_pivot):
            value = np.where(at_pivot, _ring_limit(geo, geo["D"] * np.sign(P @ geo["D"])[..., None]), value)
    return value


def _ring_limit(geo, P):
    """Q at the pivot directions P = +-D (Watt-1, where the division is 0/0): the mean over
    rings of arcs h and 2h about P, extrapolated (Richardson) to h = 0; error O(h**4)."""
    h = 0.01
    e1 = unit_rows(np.cross(P, np.where(np.abs(P[..., :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])))
    e2 = np.cross(P, e1)
    means = []
    for arc in (h, 2 * h):
        ring = [np.cos(arc) * P + np.sin(arc) * (np.cos(k * np.pi / 4) * e1 + np.sin(k * np.pi / 4) * e2)
                for k in range(8)]
        means.append(sum(_dixon(geo, q) for q in ring) / 8)
    return (4 * means[0] - means[1]) / 3


_EVALUATE = {"stephenson1": _stephenson1, "stephenson2": _dixon, "watt1": _dixon, "watt2": _watt2}


def sixbar_curve(linkage, points, *, cone=False):
    """The implicit coupler curve of a spherical six-bar, evaluated at points.

    For the six-bars of `stephenson1`, `stephenson2`, `watt1` and `watt2` (monograph §2.2,
    §2.7, §2.8, §2.9) the coupler point's curve is ``Q(x) = 0`` on the unit sphere, with Q
    the resultant of eq. (2) of the derivation: Cramer's condition (3) for Stephenson-1 and
    Watt-2, the 8 x 8 Dixon determinant for Stephenson-2 and Watt-1 (divided by
    ``|x X D|**4``). Q has degree ``m = order / 2`` and the cone over the curve,
    ``H(x) = |x|**order Q(x/|x|) Q(-x/|x|)``, has degree `order`:
    ``SIXBAR_CURVE_ORDERS = {'stephenson1': 24, 'stephenson2': 32, 'watt1': 24, 'watt2': 8}``.

    Parameters
    ----------
    linkage : SphericalLinkage
        A six-bar built by `stephenson1`, `stephenson2`, `watt1` or `watt2` (any frame and
        branches: the curve holds every assembly).
    points : array_like, shape (..., 3)
        Points; non-zero vectors, taken as the directions ``x / |x|``.
    cone : bool, optional
        Return H (homogeneous of degree `order`) instead of Q at the directions.

    Returns
    -------
    ndarray, shape (...)
        Q (or H), up to a constant factor that depends on the linkage only.

    Raises
    ------
    ValueError
        If `linkage` is not one of the four six-bars, or `points` is not finite, of shape
        (..., 3) and non-zero.

    Notes
    -----
    Derivation: :ref:`deriv-spherical-sixbar-curves`, eqs. (1)-(3). Nothing is expanded;
    a point costs a few hundred operations and, for two kinds, an 8 x 8 determinant. The
    value is zero (to rounding) where the curve is; no gradient is returned (difference
    quotients serve). Near the directions where a coefficient vanishes the value loses
    accuracy: P along the crank axis for Stephenson-1 (handled through its limit), and P
    near +-D for Watt-1, where the Dixon determinant is divided by ``|P x D|**4`` (relative
    error about 1e-16 / ``|P x D|**4``; at +-D exactly, a ring mean extrapolated to the pivot).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import stephenson2, sixbar_curve
    >>> lk = stephenson2(0.3, 0.9, 0.7, 1.0, E=(0.5, 0.6), F=(1.0, 0.8), arcs=(0.7, 0.6), coupler=(0.35, 0.5))
    >>> P = lk.solve(np.linspace(0, 2 * np.pi, 4)).points["P"]
    >>> bool(np.all(np.abs(sixbar_curve(lk, P)) < 1e-12 * np.abs(sixbar_curve(lk, [0.0, 0.6, 0.8]))))
    True
    >>> sixbar_curve(lk, np.ones((2, 5, 3)), cone=True).shape
    (2, 5)
    """
    geo = _geometry(linkage)
    cone = bool_flag("cone", cone)
    x = finite_array("points", points)
    if x.ndim == 0 or x.shape[-1] != 3:
        raise ValueError(f"Expected `points` of shape (..., 3), got shape {x.shape}")
    big = np.max(np.abs(x), axis=-1)
    if np.any(big == 0.0):
        raise ValueError(f"Expected non-zero `points`, got {x[big == 0.0][0].tolist()!r}")
    scaled = x / big[..., None]
    n = np.linalg.norm(scaled, axis=-1)
    norm = big * n                                   # |x| without overflow
    shape = x.shape[:-1]
    u = (scaled / n[..., None]).reshape(-1, 3)
    run = _EVALUATE[geo["kind"]]
    value = np.empty(u.shape[0])
    for s in range(0, u.shape[0], _BLOCK):
        blk = u[s:s + _BLOCK]
        value[s:s + _BLOCK] = run(geo, blk) * (run(geo, -blk) if cone else 1.0)
    value = value.reshape(shape)
    if cone:
        with np.errstate(over="ignore", invalid="ignore"):
            value = value * norm ** SIXBAR_CURVE_ORDERS[geo["kind"]]
        if not np.all(np.isfinite(value)):
            bad = float(norm[~np.isfinite(value)].ravel()[0])
            raise ValueError(f"Expected `points` short enough for a finite cone value (|x|**order), "
                             f"got a point of length {bad!r}")
    return value
