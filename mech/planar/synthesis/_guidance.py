"""Rigid-body guidance by RR dyads: two, three, four and five poses (textbook section 2.4, (2-38) to (2-40)).

A dyad (crank) is a fixed pivot, the centre point, and a moving pivot fixed in the guided
body, the circle point, whose positions in all the poses lie on one circle about the centre
point. Two dyads make a four-bar whose coupler is the guided body; `guidance_fourbars`
builds every such four-bar and proves it by analysis with `mech.planar.FourBar`. Four
poses leave a one-parameter family of dyads, traced as curves by `circle_point_curve`.
"""

from dataclasses import dataclass

import numpy as np

from mech._generated import displacement as _gen
from mech._validate import nonnegative_int, nonnegative_number, real_array, real_number
from mech._task import SAME, planar_dyad_error, single_roots
from mech.planar.synthesis._displacement import complex_array, pose_set

# a solution farther than this (in units of the pose set's size) is a slider, not a crank:
# its radii agree only to about its distance times the rounding, beyond any tolerance
_FAR = 1e8
# a root may move this far (relative) when polished onto the real line, and no farther
_DRIFT = 1e-2

__all__ = ["Dyad", "BurmesterPoints", "BurmesterCurve", "dyad_for_circle_point", "dyad_for_centre_point",
           "circle_point_curve", "burmester"]


@dataclass(frozen=True)
class Dyad:
    """An RR dyad (a crank) found by guidance synthesis.

    Attributes
    ----------
    circle_point : complex or ndarray of complex
        The moving pivot in body coordinates (a body point ``z`` is at
        ``exp(1j*theta)*z + d`` in pose ``(theta, d)``).
    moving_pivot : complex or ndarray of complex
        The moving pivot in the ground frame at the first pose.
    centre_point : complex or ndarray of complex
        The fixed pivot in the ground frame.
    length : float or ndarray
        The crank length, ``abs(moving_pivot - centre_point)``.
    """

    circle_point: object
    moving_pivot: object
    centre_point: object
    length: object


@dataclass(frozen=True)
class BurmesterPoints:
    """The Burmester dyads of five poses (returned by `burmester`).

    Attributes
    ----------
    dyads : tuple of Dyad
        Every real solution (0, 2 or 4 of them, 1 or 3 when one is at infinity, a slider),
        sorted by crank length.
    n_complex : int
        The number of complex (unusable) solutions among the four.
    residual : float
        The largest spread of a real dyad's radii over the five poses, relative to the pose
        set's size (each dyad listed meets its poses to ``imag_tol`` of `burmester`).
    n_infinite : int
        The number of solutions at infinity or numerically there (a circle or centre point
        more than 1e8 times the pose set's size away): sliders, not cranks, left out.
    """

    dyads: tuple
    n_complex: int
    residual: float
    n_infinite: int = 0


def _images(theta, d, z):
    """Positions exp(1j*theta_j)*z + d_j of body points z, stacked on the last axis."""
    return np.exp(1j * theta) * z[..., None] + d


def _circumcentre(w):
    """Circumcentres of the three points on the last axis of `w` (inf or NaN if collinear).

    The points are moved to the first and scaled by their spread, so squares of their
    coordinates neither overflow nor underflow at any unit of length.
    """
    rel = w - w[..., :1]
    scale = np.max(np.abs(rel), axis=-1)
    scale = np.where(scale > 0, scale, 1.0)
    rel = rel / scale[..., None]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        cx, cy = _gen.circumcentre(0.0, 0.0, rel[..., 1].real, rel[..., 1].imag, rel[..., 2].real, rel[..., 2].imag)
        return w[..., 0] + scale * (cx + 1j * cy)


def _bisector_point(w, along):
    """The point of the perpendicular bisector of w[..., 0], w[..., 1] at `along` chords from the middle."""
    return 0.5 * (w[..., 0] + w[..., 1]) + along * 1j * (w[..., 1] - w[..., 0])


def _checked_dyad(z, A, Z1, name, value, w=None, d=None):
    """A `Dyad`, after checking that every crank has a finite, non-zero length.

    With the positions `w` (last axis: the poses) and the translations `d`, a point whose
    positions coincide to `mech._task.SAME` of the task's size (the spread of `d`, or the
    point's own distance from the reference point) is a pole and refused too: its crank
    length would be rounding.
    """
    length = np.abs(Z1 - A)
    bad = ~np.isfinite(length) | (length == 0.0)
    if w is not None:
        spread = float(np.max(np.abs(d - d.mean())))
        scale = np.maximum(spread, np.abs(z))
        moved = np.max(np.abs(w - w[..., :1]), axis=-1)
        bad |= moved <= SAME * scale
    if np.any(bad):
        k = np.flatnonzero(np.ravel(bad))[0]
        raise ValueError(
            f"Expected `{name}` whose positions fix a crank of finite, non-zero length (not a pole, "
            f"not on a line through three positions), got {complex(np.ravel(value)[k])!r}"
        )
    return Dyad(z[()], Z1[()], A[()], length[()])


def dyad_for_circle_point(theta, d, circle_point, *, along=0.0):
    """The crank through two or three poses with a chosen circle point (moving pivot).

    Three poses: the centre point is the circumcentre of the three positions of the circle
    point (F63). Two poses: it may be anywhere on the perpendicular bisector of the two
    positions; `along` picks the point ``mid + along * 1j * (Z_2 - Z_1)``.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Pose angles, radians, n = 2 or 3.
    d : array_like of complex, shape (n,)
        Pose translations (the reference points).
    circle_point : array_like of complex, shape (...)
        Moving pivots in body coordinates; several at once broadcast.
    along : float, optional
        Two poses only: position on the bisector, in chord lengths from the chord's middle.

    Returns
    -------
    Dyad
        With fields of the shape of `circle_point`.

    Raises
    ------
    ValueError
        For a wrong number of poses, non-finite input, or a circle point whose positions are
        collinear (three poses) or coincide (it is a pole): no crank of finite, non-zero length.

    Notes
    -----
    Derivation of the circumcentre (differences first): :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import dyad_for_circle_point
    >>> theta, d = np.array([0.0, 0.3, 0.7]), np.array([0, 1 + 0.2j, 1.8 + 0.9j])
    >>> crank = dyad_for_circle_point(theta, d, 0.5 + 0.5j)
    >>> Z = np.exp(1j * theta) * crank.circle_point + d
    >>> bool(np.allclose(np.abs(Z - crank.centre_point), crank.length, rtol=1e-14))
    True
    """
    theta, d = pose_set(theta, d, (2, 3))
    z = complex_array("circle_point", circle_point)
    along = real_number("along", along)
    w = _images(theta, d, z)
    A = _circumcentre(w) if theta.size == 3 else _bisector_point(w, along)
    return _checked_dyad(z, A, w[..., 0], "circle_point", z, w, d)


def dyad_for_centre_point(theta, d, centre_point, *, along=0.0):
    """The crank through two or three poses with a chosen centre point (fixed pivot).

    By kinematic inversion: seen from the body, the fixed pivot takes the positions
    ``exp(-1j*theta_j)*(A - d_j)``; the circle point is their circumcentre (three poses) or a
    point of their perpendicular bisector (two poses, chosen by `along` as in
    `dyad_for_circle_point`).

    Parameters
    ----------
    theta : array_like, shape (n,)
        Pose angles, radians, n = 2 or 3.
    d : array_like of complex, shape (n,)
        Pose translations.
    centre_point : array_like of complex, shape (...)
        Fixed pivots in the ground frame.
    along : float, optional
        Two poses only: position on the bisector, in chord lengths from the chord's middle.

    Returns
    -------
    Dyad
        With fields of the shape of `centre_point`.

    Raises
    ------
    ValueError
        As `dyad_for_circle_point`, for a centre point that gives no finite crank.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import dyad_for_centre_point
    >>> theta, d = np.array([0.0, 0.3, 0.7]), np.array([0, 1 + 0.2j, 1.8 + 0.9j])
    >>> crank = dyad_for_centre_point(theta, d, -1 + 2j)
    >>> complex(np.round(crank.centre_point, 12))
    (-1+2j)
    """
    theta, d = pose_set(theta, d, (2, 3))
    A = complex_array("centre_point", centre_point)
    along = real_number("along", along)
    seen = np.exp(-1j * theta) * (A[..., None] - d)
    z = _circumcentre(seen) if theta.size == 3 else _bisector_point(seen, along)
    Z1 = np.exp(1j * theta[0]) * z + d[0]
    return _checked_dyad(z, A, Z1, "centre_point", A, seen, np.exp(-1j * theta) * d)


# --- five poses -----------------------------------------------------------------------------

def _product(X0, N, j, k, sign):
    """Coefficients [1, l, m, l^2, l m, m^2] of sign * X_j * X_k on the plane X = X0 + N t."""
    a = (X0[j], N[j, 0], N[j, 1])
    b = (X0[k], N[k, 0], N[k, 1])
    return sign * np.array([a[0] * b[0], a[0] * b[1] + a[1] * b[0], a[0] * b[2] + a[2] * b[0],
                            a[1] * b[1], a[1] * b[2] + a[2] * b[1], a[2] * b[2]])


def _constraint_conics(X0, N):
    """The conditions s1 = x p + y q and s2 = y p - x q on the plane X = X0 + N t."""
    def lin(i):
        return np.array([X0[i], N[i, 0], N[i, 1], 0.0, 0.0, 0.0])
    x, y, p, q, s1, s2 = range(6)
    Q1 = lin(s1) + _product(X0, N, x, p, -1) + _product(X0, N, y, q, -1)
    Q2 = lin(s2) + _product(X0, N, y, p, -1) + _product(X0, N, x, q, 1)
    return Q1, Q2


def _conic_eval(Q, l, m):
    return Q[0] + Q[1] * l + Q[2] * m + Q[3] * l * l + Q[4] * l * m + Q[5] * m * m


def _conic_grad(Q, l, m):
    return Q[1] + 2 * Q[3] * l + Q[4] * m, Q[2] + Q[4] * l + 2 * Q[5] * m


def _rotate(Q, c, s):
    """Coefficients of Q in coordinates (l', m') with l = c l' - s m', m = s l' + c m'."""
    q0, ql, qm, qll, qlm, qmm = Q
    return np.array([
        q0, ql * c + qm * s, -ql * s + qm * c,
        qll * c * c + qlm * c * s + qmm * s * s,
        -2 * qll * c * s + qlm * (c * c - s * s) + 2 * qmm * c * s,
        qll * s * s - qlm * c * s + qmm * c * c,
    ])


def _intersect_conics(Q1, Q2):
    """All (complex) intersections of two conics, by the resultant in one unknown.

    The coordinates are first turned so that both l^2 coefficients are large (the resultant
    in l then has full degree); each root is polished by complex Newton steps on the pair.
    """
    best = None
    for angle in np.linspace(0.0, np.pi, 13)[:-1]:
        R1, R2 = _rotate(Q1, np.cos(angle), np.sin(angle)), _rotate(Q2, np.cos(angle), np.sin(angle))
        n1, n2 = np.linalg.norm(R1[3:]), np.linalg.norm(R2[3:])
        score = min(abs(R1[3]) / n1 if n1 > 0 else 0.0, abs(R2[3]) / n2 if n2 > 0 else 0.0)
        if best is None or score > best[0]:
            best = (score, angle, R1, R2)
    _, angle, R1, R2 = best
    P = np.polynomial.polynomial
    a1, b1, c1 = R1[3], R1[[1, 4]], R1[[0, 2, 5]]
    a2, b2, c2 = R2[3], R2[[1, 4]], R2[[0, 2, 5]]
    e1 = P.polysub(a1 * c2, a2 * c1)
    e2 = P.polysub(a1 * b2, a2 * b1)
    e3 = P.polysub(P.polymul(b1, c2), P.polymul(b2, c1))
    quartic = P.polysub(P.polymul(e1, e1), P.polymul(e2, e3))
    top = np.max(np.abs(quartic))
    if not top > 0:
        raise ValueError("Expected five poses with finitely many Burmester dyads, got poses whose "
                         "two conditions share a whole curve of solutions")
    quartic = np.trim_zeros(quartic / top, "b")
    points = []
    for m in np.roots(quartic[::-1]) if quartic.size > 1 else []:
        # l from either conic's quadratic in l at this m; keep the candidate that fits both
        cands = []
        for a, b, c in ((a1, b1, c1), (a2, b2, c2)):
            bm, cm = P.polyval(m, b), P.polyval(m, c)
            cands.extend(np.roots([a, bm, cm]) if abs(a) > 0 else ([-cm / bm] if bm != 0 else []))
        if not cands:       # both conics free of l here: a root at infinity, not a crank
            continue
        l = min(cands, key=lambda v: abs(_conic_eval(R1, v, m)) + abs(_conic_eval(R2, v, m)))
        best = (np.inf, l, m)
        with np.errstate(over="ignore", invalid="ignore"):
            for _ in range(7):
                f = np.array([_conic_eval(R1, l, m), _conic_eval(R2, l, m)])
                size = np.max(np.abs(f))
                if not np.isfinite(size):
                    break
                if size < best[0]:
                    best = (size, l, m)
                J = np.array([_conic_grad(R1, l, m), _conic_grad(R2, l, m)])
                try:
                    step = np.linalg.solve(J, f)
                except np.linalg.LinAlgError:
                    break
                l, m = l - step[0], m - step[1]
        # the iterate with the smallest residual, in case a step near a singular point diverged
        _, l, m = best
        c, s = np.cos(angle), np.sin(angle)
        points.append((c * l - s * m, s * l + c * m))
    return points


def _polish(rows, X):
    """Real Newton steps on the four half-form equations (2-40) in (x, y, p, q)."""
    x, y, p, q = X
    for _ in range(8):
        s1, s2 = x * p + y * q, y * p - x * q
        F = rows[:, :6] @ np.array([x, y, p, q, s1, s2]) + rows[:, 6]
        kx, ky, kp, kq, k1, k2 = rows[:, :6].T
        J = np.stack([kx + k1 * p - k2 * q, ky + k1 * q + k2 * p,
                      kp + k1 * x + k2 * y, kq + k1 * y - k2 * x], axis=1)
        try:
            step = np.linalg.solve(J, F)
        except np.linalg.LinAlgError:
            break
        if not np.all(np.isfinite(step)) or np.max(np.abs(step)) > max(1.0, abs(x), abs(y), abs(p), abs(q)):
            break       # a step larger than the point itself: near a singular point, keep the point
        x, y, p, q = x - step[0], y - step[1], p - step[2], q - step[3]
        if np.max(np.abs(step)) <= 1e-16 * max(1.0, abs(x), abs(y), abs(p), abs(q)):
            break
    return x, y, p, q


def burmester(theta, d, *, imag_tol=1e-7, rank_tol=1e-12):
    """All Burmester dyads of five poses: every crank whose circle point meets all five.

    Each pose after the first gives one half-form equation (2-40),
    ``(|B_j - A|^2 - |B_1 - A|^2) / 2 = 0``, in the circle point ``z = x + 1j*y`` (body
    coordinates) and the centre point ``A = p + 1j*q``. The four equations are linear in
    ``x, y, p, q`` and the product ``s = z * conj(A)``; their solutions form a plane, on
    which ``s = z * conj(A)`` is a pair of conics. Their four intersections (a quartic,
    solved by `numpy.roots` on normalised data and polished by Newton's method on the
    original equations) are all the solutions.

    Parameters
    ----------
    theta : array_like, shape (5,)
        Pose angles, radians.
    d : array_like of complex, shape (5,)
        Pose translations (the reference points P_i of the textbook).
    imag_tol : float, optional
        A solution counts as real when its real part, polished by Newton's method on the
        real equations, makes a crank whose radii at the five poses differ by at most this
        times the pose set's size (the crank is verified, whatever the root's imaginary
        part was); at least 0.
    rank_tol : float, optional
        Relative size of the fourth singular value of the linear system below which the
        poses are too special (e.g. all turns about one point) for finitely many dyads.

    Returns
    -------
    BurmesterPoints
        ``dyads`` (every real solution, by crank length, each verified), ``n_complex``,
        ``residual``, ``n_infinite``. ``len(dyads) + n_complex + n_infinite`` is 4.

    Raises
    ------
    ValueError
        For a wrong number of poses, non-finite input, two poses that are the same pose
        (equal, or a whole number of turns apart), a negative or non-finite tolerance, or
        dependent design equations.

    Notes
    -----
    The data are first moved to their centroid and scaled by their size, so the result
    does not depend on the unit of length. No starting guess is needed, and no trivial
    root appears. A solution at infinity (a slider, when the quartic's leading
    coefficient vanishes), or so far away that it is one in floating point (more than 1e8
    times the pose set's size), is not a crank: it is left out of ``dyads`` and counted in
    ``n_infinite``. A root is real when its verified crank meets the task; when several
    roots polish to one crank, only the one that moved least is, and only if it moved
    much less than the others: the two roots of a complex pair, however close to the real
    line, share their real part and are both counted complex. Near a double root (two Burmester points about to
    merge) the accuracy drops as sqrt(machine epsilon).
    Derivation of the linear form: :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import burmester
    >>> P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j]
    >>> theta = np.radians([0.0, 8.88, 22.1, 63.68, -3.0])          # example 2-15
    >>> found = burmester(theta, P)
    >>> [round(float(k.length), 3) for k in found.dyads]
    [108.757, 186.698, 468.402, 1502.997]
    """
    theta, d = pose_set(theta, d, (5,))
    imag_tol = nonnegative_number("imag_tol", imag_tol)
    rank_tol = nonnegative_number("rank_tol", rank_tol)
    centre = d.mean()
    size = np.max(np.abs(d - centre))
    size = size if size > 0 else 1.0
    dn = (d - centre) / size
    rows = np.array(_gen.crank_design_row(theta[0], dn[0].real, dn[0].imag,
                                          theta[1:], dn[1:].real, dn[1:].imag), dtype=float).T
    rows = np.broadcast_to(rows, (4, 7)).copy()
    rows /= np.linalg.norm(rows, axis=1, keepdims=True)
    M = rows[:, :6]
    _, sv, Vt = np.linalg.svd(M)
    if sv[3] <= rank_tol * sv[0]:
        raise ValueError(
            "Expected five poses whose design equations (2-40) are independent, got singular values "
            f"{np.array2string(sv, precision=3)} for `theta` = {np.array2string(theta, precision=6)} "
            f"(the fourth at most `rank_tol` = {rank_tol!r} times the first)"
        )
    X0 = np.linalg.lstsq(M, -rows[:, 6], rcond=None)[0]
    N = Vt[4:].T
    Q1, Q2 = _constraint_conics(X0, N)
    roots = _intersect_conics(Q1, Q2)
    found, n_complex, n_infinite = [], 0, 4 - len(roots)
    for l, m in roots:
        X = X0 + N @ np.array([l, m])
        if not np.all(np.isfinite(X)):
            n_infinite += 1
            continue
        # the root is tried on the real line: its real part, polished by real Newton steps,
        # must make a crank that meets the five poses (verification decides, not Im X)
        x, y, p, q = _polish(rows, X.real[:4])
        z_n, A_n = x + 1j * y, p + 1j * q
        far = max(abs(z_n), abs(A_n))
        if not far < _FAR:
            n_infinite += 1             # numerically at infinity: a slider, not a crank
            continue
        error = planar_dyad_error(theta, dn, z_n, A_n)
        drift = np.max(np.abs(X[:4] - np.array([x, y, p, q]))) / max(1.0, far)
        if error <= imag_tol and drift <= _DRIFT:
            found.append((z_n, A_n, error, drift))
        else:
            n_complex += 1
    # one crank reached from several roots is listed once at most (`mech._task.single_roots`)
    keep = single_roots([f[:2] for f in found], [f[3] for f in found],
                        lambda a, b: abs(a[0] - b[0]) + abs(a[1] - b[1]) <= 1e-6 * max(1.0, *map(abs, a)))
    n_complex += len(found) - len(keep)
    dyads, worst = [], 0.0
    for z_n, A_n, error, _ in (found[k] for k in keep):
        worst = max(worst, error)
        z, A = z_n * size, centre + A_n * size
        Z1 = np.exp(1j * theta[0]) * z + d[0]
        dyads.append(Dyad(complex(z), complex(Z1), complex(A), float(abs(Z1 - A))))
    dyads.sort(key=lambda k: k.length)
    return BurmesterPoints(tuple(dyads), n_complex, worst, n_infinite)


# --- four poses: the circle-point and centre-point curves (Burmester's cubics), as curves ---------
@dataclass(frozen=True)
class BurmesterCurve:
    """The circle-point curve of four poses and the matching centre points.

    The curve is traced by lines through a pole P_jk (a point of the curve): the line at
    angle ``phi[i]`` meets the cubic in the pole and in two more points, ``k = 0, 1``.

    Attributes
    ----------
    phi : ndarray, shape (m,)
        Directions of the tracing lines, radians.
    circle_point : ndarray of complex, shape (m, 2)
        Circle points in body coordinates; NaN where the two further intersections are
        complex or at infinity (``valid`` False).
    moving_pivot, centre_point : ndarray of complex, shape (m, 2)
        The circle point in the ground frame at pose 1, and its centre point.
    length : ndarray, shape (m, 2)
        Crank lengths.
    valid : ndarray of bool, shape (m, 2)
        True where the intersection is real and finite and its crank, checked at the four
        poses, meets them (radii equal to 1e-7 of the larger of the pose set's size and
        the crank).
    pole : complex
        The pole (body coordinates) the tracing lines pass through.
    """

    phi: np.ndarray
    circle_point: np.ndarray
    moving_pivot: np.ndarray
    centre_point: np.ndarray
    length: np.ndarray
    valid: np.ndarray
    pole: complex

    def dyad(self, i, k):
        """The `Dyad` at tracing line `i`, intersection `k` (0 or 1); it must be valid."""
        i = nonnegative_int("i", i, self.phi.size - 1)
        k = nonnegative_int("k", k, 1)
        if not self.valid[i, k]:
            raise ValueError(f"Expected a valid point of the curve, got i = {i}, k = {k} (complex or infinite)")
        return Dyad(complex(self.circle_point[i, k]), complex(self.moving_pivot[i, k]),
                    complex(self.centre_point[i, k]), float(self.length[i, k]))


def _rows_at(rows, z):
    """The three equations at circle points z (shape (m,)), as rows [coef p, coef q, constant]
    of a linear system for the centre point; shape (m, 3, 3)."""
    kx, ky, kp, kq, k1, k2, k0 = (rows[:, i][None, :] for i in range(7))
    x, y = z.real[:, None], z.imag[:, None]
    return np.stack([kp + k1 * x + k2 * y, kq + k1 * y - k2 * x, kx * x + ky * y + k0], axis=-1)


def _affine_rows(rows, z0, v):
    """The rows along the lines z = z0 + r v, as affine functions a + b r; shape (m, 3, 3, 2)."""
    a = _rows_at(rows, np.full(v.shape, z0))
    b = _rows_at(rows, v) - _rows_at(rows, np.zeros_like(v))
    return np.stack([a, b], axis=-1)


def _pmul(f, g):
    """Product of polynomials in r stored along the last axis (lowest degree first)."""
    out = np.zeros(np.broadcast_shapes(f.shape[:-1], g.shape[:-1]) + (f.shape[-1] + g.shape[-1] - 1,))
    for i in range(f.shape[-1]):
        for j in range(g.shape[-1]):
            out[..., i + j] += f[..., i] * g[..., j]
    return out


def _det_cubic(E):
    """Coefficients (r^0 .. r^3) of the determinant of 3x3 matrices with affine entries E."""
    def e(i, j):
        return E[:, i, j]
    terms = [(+1, (0, 0), (1, 1), (2, 2)), (-1, (0, 0), (1, 2), (2, 1)), (-1, (0, 1), (1, 0), (2, 2)),
             (+1, (0, 1), (1, 2), (2, 0)), (+1, (0, 2), (1, 0), (2, 1)), (-1, (0, 2), (1, 1), (2, 0))]
    return sum(s * _pmul(_pmul(e(*p), e(*q)), e(*t)) for s, p, q, t in terms)


def circle_point_curve(theta, d, *, samples=360, phi=None):
    """The circle-point curve of four poses, with the centre point of each of its points.

    For four poses the three equations (2-40) leave one degree of freedom: the circle points
    (body points whose four positions lie on a circle) form a cubic curve, and their centres
    another cubic, the centre-point curve. Each line through a pole of two of the poses (a
    point of the curve) meets the cubic in two more points, the roots of a quadratic; the
    lines at ``samples`` directions trace the whole curve.

    Parameters
    ----------
    theta : array_like, shape (4,)
        Pose angles, radians.
    d : array_like of complex, shape (4,)
        Pose translations.
    samples : int, optional
        Number of tracing directions, evenly spread over [0, pi), at least 1.
    phi : array_like, shape (m,), optional
        Tracing directions (radians) to use instead of `samples` even ones.

    Returns
    -------
    BurmesterCurve
        ``circle_point``, ``moving_pivot``, ``centre_point``, ``length`` and ``valid`` of
        shape (samples, 2); ``dyad(i, k)`` gives one point as a `Dyad`.

    Raises
    ------
    ValueError
        For a wrong number of poses or non-finite input, or if every two poses differ by a
        pure translation (no pole to trace from).

    Notes
    -----
    The poses are moved to their centroid and scaled by their size first, so the curve
    does not depend on the unit of length. For each circle point the centre point solves
    the three (consistent) linear equations by least squares. Derivation of the equations:
    :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import circle_point_curve
    >>> theta, d = np.radians([0.0, 8.88, 22.1, 63.68]), [13.84 + 188.47j, -31.07 + 140.64j,
    ...                                                   -51.64 + 96.33j, 44.74 + 113.95j]
    >>> curve = circle_point_curve(theta, d, samples=90)
    >>> Z = np.exp(1j * theta) * curve.circle_point[curve.valid][:, None] + d
    >>> r = np.abs(Z - curve.centre_point[curve.valid][:, None])
    >>> bool(np.all(np.abs(r - r[:, :1]) < 1e-9 * r[:, :1]))
    True
    """
    theta, d = pose_set(theta, d, (4,))
    if phi is None:
        samples = nonnegative_int("samples", samples, 10**7)
        if samples < 1:
            raise ValueError(f"Expected `samples` >= 1, got {samples}")
        phi = np.arange(samples) * (np.pi / samples)
    else:
        phi = real_array("phi", phi).reshape(-1)
        samples = phi.size
    centre = d.mean()
    size = np.max(np.abs(d - centre))
    size = size if size > 0 else 1.0
    dn = (d - centre) / size
    w = np.exp(1j * theta)
    # trace from the pole of the two poses that turn most relative to each other
    j, k = max(((j, k) for j in range(4) for k in range(j + 1, 4)), key=lambda jk: abs(w[jk[0]] - w[jk[1]]))
    if abs(w[j] - w[k]) == 0:
        raise ValueError(f"Expected poses that turn relative to each other, got `theta` = {theta!r}")
    z0 = (dn[k] - dn[j]) / (w[j] - w[k])
    rows = np.array(_gen.crank_design_row(theta[0], dn[0].real, dn[0].imag,
                                          theta[1:], dn[1:].real, dn[1:].imag), dtype=float).T
    rows = np.broadcast_to(rows, (3, 7)).copy()
    rows /= np.linalg.norm(rows, axis=1, keepdims=True)
    v = np.exp(1j * phi)
    cubic = _det_cubic(_affine_rows(rows, z0, v))
    # r = 0 (the pole) is a root; the other two solve c3 r^2 + c2 r + c1 = 0
    c1, c2, c3 = cubic[:, 1], cubic[:, 2], cubic[:, 3]
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        disc = c2 * c2 - 4 * c3 * c1
        root = np.sqrt(np.where(disc >= 0, disc, np.nan))
        q = -0.5 * (c2 + np.where(c2 >= 0, 1.0, -1.0) * root)
        r = np.stack([q / c3, c1 / q], axis=-1)
        valid = np.isfinite(r)
        z = np.where(valid, z0 + r * v[:, None], z0)
    M = _rows_at(rows, z.ravel())
    pq = np.einsum("nij,nj->ni", np.linalg.pinv(M[:, :, :2]), -M[:, :, 2])
    A = (pq[:, 0] + 1j * pq[:, 1]).reshape(samples, 2)
    zb = np.where(valid, z, np.nan) * size
    Ab = np.where(valid, centre + A * size, np.nan)
    moving = np.exp(1j * theta[0]) * zb + d[0]
    length = np.abs(moving - Ab)
    valid &= np.isfinite(length) & (length > 0)
    # every point kept is verified: its four radii agree (normalised units) to 1e-7 of the
    # larger of the pose set's size and its crank; the rest are marked not valid
    with np.errstate(invalid="ignore", over="ignore"):
        radii = np.abs(np.exp(1j * theta) * z[..., None] + dn - A[..., None])
        spread = np.max(radii, axis=-1) - np.min(radii, axis=-1)
    valid &= spread <= 1e-7 * np.maximum(1.0, np.max(radii, axis=-1))
    nan = complex(np.nan, np.nan)
    return BurmesterCurve(phi, np.where(valid, zb, nan), np.where(valid, moving, nan),
                          np.where(valid, Ab, nan), np.where(valid, length, np.nan), valid, complex(z0 * size))
