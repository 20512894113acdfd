"""Burmester theory on the sphere (the spherical monograph, §3.3 to §3.6): the slider-point
cubic of three orientations, the circle-point and centre-point cubics and the slider points
of four, and the Burmester points of five, the real roots of a sextic.
"""

from dataclasses import dataclass

import numpy as np

from mech._validate import nonnegative_int, nonnegative_number, real_array
from mech.spherical.guidance._dyads import SphericalDyad, arc_between, make_dyad
from mech._task import single_roots, spherical_dyad_error

# a root may lie this far from the polished crank's root on the unit circle, and no farther
_DRIFT = 0.5
# a crank whose arcs agree to this (relative to its movement) needs no further polishing;
# 0: every polish is tried and the best kept (at 1e-13 a Stephenson-2 designed from these
# cranks closed its loops only to 2.6e-11 after the generated kernels moved to hypot forms)
_ROUNDING = 0.0
from mech.spherical.guidance._orientations import _axis_angle, _parts, orientation_set

__all__ = ["SphericalBurmesterCurve", "SphericalBurmesterPoints", "circle_point_curve", "slider_point_curve",
           "burmester", "slider_dyads"]


@dataclass(frozen=True)
class SphericalBurmesterCurve:
    """A Burmester cubic on the sphere, traced by great circles through a pole.

    The great circle through ``pole`` at direction ``phi[i]`` meets the cubic cone in the
    pole and in two more axes, ``k = 0, 1``.

    Attributes
    ----------
    phi : ndarray, shape (m,)
        Directions of the tracing great circles at the pole, radians in [0, pi).
    circle_point : ndarray, shape (m, 2, 3)
        Circle points (or slider points) in body coordinates; NaN where not real.
    moving_pivot : ndarray, shape (m, 2, 3)
        The same in the ground frame at the first orientation (the circle-point curve).
    centre_point : ndarray, shape (m, 2, 3)
        Their centre points (the centre-point curve), or the guides' poles for sliders.
    arc : ndarray, shape (m, 2)
        Crank arcs in (0, pi/2].
    valid : ndarray of bool, shape (m, 2)
        True where the point is real and verified: its positions are equidistant from the
        centre point (on the guide, for sliders) to 1e-9 of the displacements.
    pole : ndarray, shape (3,)
        The pole (ground frame) the tracing great circles pass through.
    """

    phi: np.ndarray
    circle_point: np.ndarray
    moving_pivot: np.ndarray
    centre_point: np.ndarray
    arc: np.ndarray
    valid: np.ndarray
    pole: np.ndarray

    def dyad(self, i, k):
        """The `SphericalDyad` at tracing circle `i`, point `k` (0 or 1); it must be valid."""
        i = nonnegative_int("i", i, self.phi.size - 1)
        k = nonnegative_int("k", k, 1)
        if not self.valid[i, k]:
            raise ValueError(f"Expected a valid (real) point of the curve, got i = {i}, k = {k}")
        return SphericalDyad(self.circle_point[i, k].copy(), self.moving_pivot[i, k].copy(),
                             self.centre_point[i, k].copy(), float(self.arc[i, k]))


@dataclass(frozen=True)
class SphericalBurmesterPoints:
    """The Burmester dyads of five orientations (returned by `burmester`).

    Attributes
    ----------
    dyads : tuple of SphericalDyad
        Every real solution (0, 2, 4 or 6), sorted by arc.
    n_complex : int
        The number of complex (unusable) solutions among the six.
    residual : float
        Largest design-equation residual (4) over the real dyads, each equation scaled by
        the size of its displacement.
    sextic : ndarray of complex, shape (7,)
        Coefficients (lowest degree first) of the sextic (10) in ``x = exp(2j*phi)``, phi
        the direction at ``pole`` of the great circle through a Burmester point; real
        solutions are its roots with ``|x| = 1``.
    pole : ndarray, shape (3,)
        The pole the directions are measured at.
    n_double : int
        0 or 1: 1 when two real solutions meet at one listed dyad (a double root, or two
        roots closer than double precision tells apart), so that the real solutions
        number ``len(dyads) + n_double`` and, with `n_complex`, make six.
    """

    dyads: tuple
    n_complex: int
    residual: float
    sextic: np.ndarray
    pole: np.ndarray
    n_double: int = 0


def _basis(P):
    """Two unit vectors completing the unit vector P to a right-handed frame."""
    a = np.array([1.0, 0.0, 0.0]) if abs(P[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(P, a)
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(P, e1)


def _det(a, b, c):
    return np.sum(a * np.cross(b, c), axis=-1)


def _cubic_on_circles(M, P, v):
    """Coefficients c1, c2, c3 of det[M_k (P + r v)] / r on great circles through P.

    ``M`` is three 3x3 matrices; P a point of the cubic (c0 = 0); ``v`` shape (m, 3).
    """
    a = [Mk @ P for Mk in M]
    b = [v @ Mk.T for Mk in M]
    c1 = _det(b[0], a[1], a[2]) + _det(a[0], b[1], a[2]) + _det(a[0], a[1], b[2])
    c2 = _det(a[0], b[1], b[2]) + _det(b[0], a[1], b[2]) + _det(b[0], b[1], a[2])
    c3 = _det(b[0], b[1], b[2])
    return c1, c2, c3


def _trace(M, P, phi):
    """The two further axes of the cubic det[M_k w] = 0 on each great circle through P."""
    e1, e2 = _basis(P)
    v = np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2
    c1, c2, c3 = _cubic_on_circles(M, P, v)
    scale = np.maximum(np.max(np.abs(np.stack([c1, c2, c3])), axis=0), np.finfo(float).tiny)
    c1, c2, c3 = c1 / scale, c2 / scale, c3 / scale
    disc = c2 * c2 - 4.0 * c1 * c3
    with np.errstate(invalid="ignore"):
        q = -0.5 * (c2 + np.where(c2 >= 0.0, 1.0, -1.0) * np.sqrt(np.where(disc >= 0.0, disc, np.nan)))
    # the roots r = q / c3 and r = c1 / q, homogeneous: w ~ c3 P + q v and w ~ q P + c1 v
    w = np.stack([c3[:, None] * P + q[:, None] * v, q[:, None] * P + c1[:, None] * v], axis=1)
    norm = np.linalg.norm(w, axis=-1, keepdims=True)
    valid = (disc >= 0.0)[:, None] & (norm[..., 0] > 0.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        w = np.where(valid[..., None], w / norm, np.nan)
    return w, valid


def _null(rows):
    """Unit null vectors of stacks of row sets (..., m, 3), by the SVD."""
    return np.linalg.svd(rows)[2][..., -1, :]


def _largest_pole(K):
    """Index and unit axis of the displacement with the largest turn."""
    axes, angles = _axis_angle(K)
    j = int(np.argmax(angles))
    if not angles[j] > 0.0:
        raise ValueError("Expected orientations that differ, got `R` with all orientations equal")
    return j, axes[j]


def _curve(R, M, P, phi, rows_of, base_index):
    w, valid = _trace(M, P, phi)
    flat = np.where(valid[..., None], w, 0.0).reshape(-1, 3)
    rows = rows_of(flat)
    u = _null(rows).reshape(w.shape)
    u = np.where(np.sum(u * w, axis=-1, keepdims=True) < 0.0, -u, u)
    arc = arc_between(u, w)
    valid &= arc > 0.0
    # every point kept is verified: u is orthogonal to each row (an equal arc, or a position
    # on the guide) to 1e-9 of the row's length; the rest are marked not valid
    scale = np.maximum(np.linalg.norm(rows, axis=-1), np.finfo(float).tiny)
    miss = np.max(np.abs(np.einsum("nij,nj->ni", rows, u.reshape(-1, 3))) / scale, axis=-1)
    valid &= (miss <= 1e-9).reshape(valid.shape)
    z = np.einsum("ji,...j->...i", R[0], w)              # body coordinates: R_1^T w
    nan = np.where(valid[..., None], 0.0, np.nan)
    return SphericalBurmesterCurve(phi, z + nan, w + nan, u + nan, np.where(valid, arc, np.nan), valid, P)


def _phis(samples, phi):
    if phi is None:
        samples = nonnegative_int("samples", samples, 10**7)
        if samples < 1:
            raise ValueError(f"Expected `samples` >= 1, got {samples}")
        return np.arange(samples) * (np.pi / samples)
    return real_array("phi", phi).reshape(-1)


def circle_point_curve(R, *, samples=360, phi=None):
    """The circle-point and centre-point curves of four orientations (§3.4), as curves.

    The circle points of four orientations (body axes whose four positions lie on one
    circle) form the cubic cone ``det[K_2 w, K_3 w, K_4 w] = 0`` (eq. (8)); their centres
    form the centre-point cubic. Each great circle through the pole of the two orientations
    that differ most meets the circle-point cubic in two more axes, the roots of a
    quadratic; the great circles at ``samples`` directions trace the curve.

    Parameters
    ----------
    R : array_like, shape (4, 3, 3)
        Orientations.
    samples : int, optional
        Number of tracing directions over [0, pi), at least 1.
    phi : array_like, optional
        Tracing directions (radians) instead of `samples` even ones.

    Returns
    -------
    SphericalBurmesterCurve
        ``moving_pivot`` (the circle-point curve, ground frame at orientation 1),
        ``centre_point`` (the centre-point curve), ``circle_point``, ``arc``, ``valid``.
        Each axis is one point of the sphere; its antipode is on the curve too.

    Raises
    ------
    ValueError
        For a wrong number of orientations, bad input, or all four orientations equal.

    Notes
    -----
    Eq. (8) of :ref:`deriv-spherical-guidance`. As the arcs shrink the curves tend to the
    planar ones of `mech.planar.synthesis.circle_point_curve` (tested).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import circle_point_curve, rotation_matrix
    >>> R = np.stack([rotation_matrix(a, t) for a, t in
    ...               [([0, 0, 1], 0.0), ([0.2, 0.1, 1], 0.5), ([-0.3, 0.2, 1], 1.0), ([0.1, -0.4, 1], 1.4)]])
    >>> curve = circle_point_curve(R, samples=60)
    >>> w, u = curve.moving_pivot[curve.valid], curve.centre_point[curve.valid]
    >>> arcs = np.stack([np.einsum("mi,mi->m", w @ (Rj @ R[0].T).T, u) for Rj in R])
    >>> bool(np.max(np.ptp(arcs, axis=0)) < 1e-12)
    True
    """
    R = orientation_set("R", R, (4,))
    phi = _phis(samples, phi)
    K = _parts(R[0], R[1:])
    j, P = _largest_pole(K)

    def rows_of(w):
        return np.stack([w @ Kj.T for Kj in K], axis=1)

    return _curve(R, list(K), P, phi, rows_of, j)


def slider_point_curve(R, *, samples=360, phi=None):
    """The slider points of three orientations (§3.3): a cubic curve on the sphere.

    A body axis is a slider point when its three positions lie on one great circle,
    ``det[w, D_21 w, D_31 w] = 0`` (eq. (7)); the guide's pole is the normal of that great
    circle. The curve is traced like `circle_point_curve`, by great circles through the
    pole P_12 (or P_13).

    Parameters
    ----------
    R : array_like, shape (3, 3, 3)
        Orientations.
    samples : int, optional
        Number of tracing directions over [0, pi).
    phi : array_like, optional
        Tracing directions instead of `samples` even ones.

    Returns
    -------
    SphericalBurmesterCurve
        ``circle_point`` (the slider points, body), ``moving_pivot`` (ground, orientation 1),
        ``centre_point`` (the guides' poles) and ``arc`` (pi/2).

    Raises
    ------
    ValueError
        For a wrong number of orientations, bad input, or equal orientations.

    Notes
    -----
    Eq. (7) of :ref:`deriv-spherical-guidance`. In the planar limit the cubic tends to the
    slider-point circle of three poses (`mech.planar.synthesis.slider_point_circle`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import slider_point_curve, rotation_matrix
    >>> R = np.stack([np.eye(3), rotation_matrix([0.2, 0.1, 1], 0.5), rotation_matrix([-0.3, 0.2, 1], 1.0)])
    >>> curve = slider_point_curve(R, samples=30)
    >>> bool(np.allclose(curve.arc[curve.valid], np.pi / 2))
    True
    """
    R = orientation_set("R", R, (3,))
    phi = _phis(samples, phi)
    K = _parts(R[0], R[1:])
    j, P = _largest_pole(K)

    def rows_of(w):
        return np.stack([w, w + w @ K[0].T, w + w @ K[1].T], axis=1)

    return _curve(R, [np.eye(3), K[0], K[1]], P, phi, rows_of, j)


def _polish(K, u, w):
    """Newton steps on the six equations u^T K_j w = 0, |u| = |w| = 1 (four matrices K_j)."""
    for _ in range(8):
        F = np.concatenate([np.einsum("i,jik,k->j", u, K, w), [(u @ u - 1) / 2, (w @ w - 1) / 2]])
        J = np.zeros((6, 6))
        J[:4, :3] = K @ w
        J[:4, 3:] = np.einsum("i,jik->jk", u, K)
        J[4, :3], J[5, 3:] = u, w
        try:
            step = np.linalg.solve(J, F)
        except np.linalg.LinAlgError:
            break
        if not np.all(np.isfinite(step)) or np.max(np.abs(step)) > 0.5:
            break
        u, w = u - step[:3], w - step[3:]
        if np.max(np.abs(step)) <= 1e-16:
            break
    return u / np.linalg.norm(u), w / np.linalg.norm(w)


def _chord_system(K, u, w):
    """The six equations of `_polish_chords` at (u, w) and their Jacobian."""
    c = K @ w                                              # chords, shape (4, 3)
    a = u - w - 0.5 * c                                    # u - m_j
    F = np.concatenate([np.sum(a * c, axis=1), [(u @ u - 1) / 2, (w @ w - 1) / 2]])
    J = np.zeros((6, 6))
    J[:4, :3] = c
    J[:4, 3:] = np.einsum("ji,jik->jk", a, K) - c - 0.5 * np.einsum("ji,jik->jk", c, K)
    J[4, :3], J[5, 3:] = u, w
    return F, J


def _conditioning(K, u, w):
    """Smallest singular value of the chord equations' Jacobian at (u, w), relative."""
    S = np.linalg.svd(_chord_system(K, u, w)[1], compute_uv=False)
    return S[-1] / S[0]


def _pair_model(K, u, w):
    """The quadratic model of the crank equations along their null direction at (u, w):
    ``l . F(p + t v) = g0 + g1 t + g2 t^2 / 2``, as (v, g0, g1, g2)."""
    U, S, Vt = np.linalg.svd(_chord_system(K, u, w)[1])
    l, v = U[:, -1], Vt[-1]
    tau = 1e-3 * max(np.linalg.norm(u - w), np.finfo(float).tiny)
    g = [l @ _chord_system(K, u + t * v[:3], w + t * v[3:])[0] for t in (-tau, 0.0, tau)]
    return v, g[1], (g[2] - g[0]) / (2 * tau), (g[2] + g[0] - 2 * g[1]) / tau ** 2


def _pair_is_real(K, u, w):
    """Whether the two solutions merged at the crank (u, w) (a double root, or two roots too
    close to tell apart) are real: the quadratic model of the equations along the
    Jacobian's null direction (`_pair_model`) has real roots."""
    _, g0, g1, g2 = _pair_model(K, u, w)
    return g1 * g1 - 2.0 * g2 * g0 >= 0.0


def _snapped(R, K, u, w):
    """The crank (u, w) moved to the nearest root of its quadratic model (`_pair_model`) and
    polished there by steps shorter than a quarter of the distance to the model's other
    root, with its error (`_dyad_error`); None when the model has no real root.

    A start between two real cranks a little apart may stop where the equations are small
    but not zero; this takes it to one of the two (a simple crank is moved by rounding only).
    """
    v, g0, g1, g2 = _pair_model(K, u, w)
    disc = g1 * g1 - 2.0 * g2 * g0
    if not disc >= 0.0:
        return None
    if g2 == 0.0:
        t, gap = (-g0 / g1 if g1 != 0.0 else 0.0), np.inf
    else:
        # the root of smaller size, without cancellation
        q = -(g1 + np.copysign(np.sqrt(disc), g1))
        t = 2.0 * g0 / q if q != 0.0 else -g1 / g2
        gap = 2.0 * np.sqrt(disc) / abs(g2)
    u1, w1 = u + t * v[:3], w + t * v[3:]
    u1, w1 = _polish_chords(K, u1, w1, limit=min(0.25 * gap, 0.1 * np.linalg.norm(u1 - w1)))
    u1 = u1 if u1 @ w1 >= 0.0 else -u1
    return _dyad_error(R, u1, w1), u1, w1


def _polish_chords(K, u, w, limit=0.5):
    """Newton steps on the crank equations in chord form, then |u| = |w| = 1.

    ``u . (w_j - w_1) = 0`` is written ``(u - m_j) . c_j = 0`` with the chord
    ``c_j = K_j w`` and its middle ``m_j = w + c_j / 2`` (equal to ``u^T K_j w`` since D_j is a
    rotation); near the planar limit both factors are small and nothing cancels, where
    ``u^T K_j w`` loses the square of the arcs to rounding. A step longer than `limit` ends
    the iteration (a start known to be close must not jump to another crank).
    """
    for _ in range(10):
        F, J = _chord_system(K, u, w)
        try:
            step = np.linalg.solve(J, F)
        except np.linalg.LinAlgError:
            break
        if not np.all(np.isfinite(step)) or np.max(np.abs(step)) > limit:
            break
        u, w = u - step[:3], w - step[3:]
        if np.max(np.abs(step)) <= 1e-17:
            break
    return u / np.linalg.norm(u), w / np.linalg.norm(w)


def _dyad_error(R, u, w):
    """`mech._task.spherical_dyad_error` of the crank (u, w), inf when not finite."""
    if not (np.all(np.isfinite(u)) and np.all(np.isfinite(w))):
        return np.inf
    return spherical_dyad_error(R, R[0].T @ w, u)


def _deflate(coef, root):
    """Divide the polynomial (lowest degree first) by (x - root); synthetic division."""
    n = coef.size - 1
    out = np.zeros(n, dtype=complex)
    acc = coef[n]
    for k in range(n - 1, -1, -1):
        out[k] = acc
        acc = coef[k] + root * acc
    return out


def burmester(R, *, imag_tol=1e-9):
    """All Burmester dyads of five orientations: every spherical crank that meets all five.

    The four design equations (4) are bilinear in the fixed axis u and the moving axis w;
    they have six solutions (complex included). The circle points are the common points of
    the circle-point cubics of orientations (1, a, b, c) and (1, a, b, d) less the three
    points both contain for any data (the poles P_1a, P_1b and the image of P_ab). Great
    circles through P_1a meet each cubic in two more points; they share one where the
    resultant (9), a binary form of degree 8 in the circle's direction, vanishes; dividing
    out the two known directions leaves the sextic (10). Its roots on the unit circle are
    the real solutions, polished by Newton's method on the six equations.

    Which roots are real is decided by verifying the cranks, not by their distance from the
    unit circle (near the planar limit the sextic's real roots drift from it, by 1e-4 at
    arcs of 1e-6 and by 0.1 at 1e-8): every root within 0.5 of the circle is moved onto
    it, its crank polished (in the cosine form of eq. (4) and in the chord form, see
    `_polish_chords`), and the crank kept when its arcs at the five orientations agree to
    ``imag_tol`` times the largest arc its body point moves. When the poles of the four
    displacements lie within a small cap (arcs of 0.1 rad or less), the cranks of the planar
    task the orientations approach (`_planar_starts`) are polished and verified too: they lie
    within the square of the cap of the spherical ones, where the sextic's roots may have
    drifted too far to lead to them. Each verified crank is then moved to the nearest root
    of the quadratic model of the equations along their null direction and polished again
    (`_snapped`): a point where a complex pair of nearly equal solutions nearly vanishes
    (its real part passes the verification) has a model without real roots and is dropped,
    and a start stopped between two real cranks close together reaches one of them. A crank
    reached from several starts (or its antipode) is one solution; the real solutions are the distinct verified cranks. Complex solutions
    come in pairs, so an odd number of cranks means two solutions meet at one of them (the
    one where the equations are nearest singular): the quadratic model of the equations
    along their null direction there says whether the two are real (the dyad is listed once
    and `n_double` is 1) or a complex pair (the dyad is not listed).

    Parameters
    ----------
    R : array_like, shape (5, 3, 3)
        Orientations, no two the same.
    imag_tol : float, optional
        Largest spread of a kept crank's arcs, relative to the largest arc its body point
        moves between two orientations; at least 0. Real cranks polish to 1e-11 or less
        (7e-12 the worst of 130 sets near the planar limit); the real parts of a complex
        pair whose imaginary parts are about sqrt(imag_tol) pass too.

    Returns
    -------
    SphericalBurmesterPoints
        ``dyads`` (every real solution, by arc, each verified), ``n_double`` (1 when two
        real solutions meet at one listed dyad), ``n_complex`` (the other solutions; the
        three add up to 6), ``residual``, ``sextic``.

    Raises
    ------
    ValueError
        For a wrong number of orientations, bad input, two orientations that are the same,
        a negative or non-finite `imag_tol`, or orientations too special for finitely many
        solutions (e.g. all turning about one axis).

    Notes
    -----
    Eqs. (4), (8)-(10) of :ref:`deriv-spherical-guidance`. The resultant is sampled at 16
    directions and its coefficients taken by a discrete Fourier transform, exact for a form
    of degree 8. Near a double root (two Burmester points about to merge) the accuracy
    drops to about sqrt(machine epsilon), before polishing. The planar counterpart has at
    most four solutions (`mech.planar.synthesis.burmester`); as the arcs shrink four spherical
    solutions tend to the planar ones and the other two become complex. The equations hold
    the turns of the orientations at full size but their translations only at the size of
    the arcs, and the cosine form (4) keeps them only at the square of the arcs; the chord
    form keeps the cranks accurate to rounding (relative to the arcs). The sextic alone
    loses real cranks below arcs of about 1e-7 rad (its roots move by 0.1 and more); with
    the planar starts, for 200 random planar pose sets and 50 near-degenerate ones carried
    onto caps of 1e-5 to 1e-8 rad per unit length, the count of real cranks agrees with a
    60-digit solve of the same orientations (each float64 matrix read as the rotation
    nearest it: at such caps its rounding off a rotation is as large as the task) (tested).
    For sets 1e-9 to 1e-11 (in a pose's position) from a planar double root, carried onto
    caps of 1e-5 to 1e-8 (two solutions about 1e-5 of the arcs apart), 191 of 192 counts
    agree with that solve (six such families); the one left, at a cap of 1e-8, is a real
    pair about 3e-6 apart that no start reaches.
    For Example 2-15 carried to the sphere
    by `planar_orientations` at scale s, all four cranks are found from s = 1e-3 to 3e-8;
    the best four-bar reproduces the orientations to 1e-15 rad at s = 1e-3, 2e-14 at 1e-4,
    9e-13 at 1e-5, 6e-11 at 1e-6 and 2e-8 at 1e-7 (its analysis loses accuracy too), and
    `guidance_fourbars` with its default ``rtol=1e-9`` passes none below s = 1e-6.

    Examples
    --------
    Example 2-15 of the planar chapter on a sphere of radius 1000 (arcs in milliradians
    are close to the planar lengths 108.757, 186.698, 468.402, 1502.997 for the short
    cranks; the long ones feel the curvature):

    >>> import numpy as np
    >>> from mech.spherical import burmester, planar_orientations
    >>> P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j]
    >>> R = planar_orientations(np.radians([0.0, 8.88, 22.1, 63.68, -3.0]), P, 1e-3)
    >>> found = burmester(R)
    >>> [round(float(k.arc) * 1e3, 3) for k in found.dyads], found.n_complex
    ([108.836, 187.013, 378.454, 823.233], 2)
    """
    R = orientation_set("R", R, (5,))
    imag_tol = nonnegative_number("imag_tol", imag_tol)
    K = _parts(R[0], R[1:])
    sizes = np.linalg.norm(K, axis=(1, 2))
    if np.any(sizes == 0.0):
        raise ValueError("Expected five different orientations, got `R` with an orientation equal to the first")
    K = K / sizes[:, None, None]
    _, angles = _axis_angle(K * sizes[:, None, None])
    # the pair (a, b) whose three spurious points are best separated
    best = None
    for a in range(4):
        for b in range(a + 1, 4):
            Kab = (K[b] * sizes[b] - K[a] * sizes[a])
            rel = np.eye(3) + K[a].T * sizes[a]
            _, ang_ab = _axis_angle(rel @ Kab)
            score = min(angles[a], angles[b], ang_ab)
            if best is None or score > best[0]:
                best = (score, a, b)
    _, a, b = best
    c, d = [k for k in range(4) if k not in (a, b)]
    Pa = _axis_angle(K[a] * sizes[a])[0]
    Pb = _axis_angle(K[b] * sizes[b])[0]
    Pab = _axis_angle((np.eye(3) + K[a].T * sizes[a]) @ (K[b] * sizes[b] - K[a] * sizes[a]))[0]
    Ma, Mb = [K[a], K[b], K[c]], [K[a], K[b], K[d]]
    coef, e1, e2 = _pencil_resultant(Ma, Mb, Pa)                     # x^0 .. x^8, x = exp(2j phi)
    top = np.max(np.abs(coef))
    if not top > 0.0:
        raise ValueError("Expected five orientations with finitely many Burmester dyads, got `R` whose two "
                         "cubics share a whole curve")
    coef = coef / top
    for S in (Pb, Pab):
        s = S - (S @ Pa) * Pa
        coef = _deflate(coef, np.exp(2j * np.arctan2(s @ e2, s @ e1)))
    sextic = coef
    roots = np.roots(np.trim_zeros(sextic[::-1], "f")) if np.any(sextic[1:] != 0) else np.array([])
    K0 = K * sizes[:, None, None]
    starts = []
    for x in roots:
        if not abs(abs(x) - 1.0) <= _DRIFT:
            continue                    # its projection is farther than _DRIFT: no need to polish
        # every root is tried on the unit circle (x / |x|: a real great circle through Pa);
        # the crank it gives, polished, must meet the five orientations (verification
        # decides, not the distance of x from the circle)
        w = _common_point(Ma, Mb, Pa, e1, e2, x / abs(x) if abs(x) > 0 else 1.0)
        u0 = _null(np.stack([Kj @ w for Kj in K]))
        starts.append((u0 if u0 @ w >= 0.0 else -u0, w))
    # near the planar limit the sextic's roots drift far from their places (its coefficients
    # hold the task only at the square of the arcs); the planar task the orientations approach
    # gives starts within the square of the arcs of the spherical cranks instead
    starts = [(u0, w, False) for u0, w in starts] + [(u0, w, True) for u0, w in _planar_starts(K0)]
    found = []
    for u0, w, close in starts:
        error, u, w = _polished(R, K, K0, u0, w, close)
        if error <= imag_tol and arc_between(u, w) > 0.0:
            found.append((u, w, error))
    # near a complex pair of nearly equal solutions the equations nearly vanish at its real
    # part (by the square of the pair's imaginary part: 1e-10 for pairs 1e-5 of the arcs
    # apart), so such points pass the verification above, from several starts; the quadratic
    # model along the equations' null direction tells them from real cranks (at a real
    # crank it has a real root, at the real part of a complex pair none); a point between
    # two real cranks close together is moved onto the nearer one (`_snapped`)
    found = [f for f in (_snapped(R, K0, u, w) for u, w, _ in found) if f is not None and f[0] <= imag_tol]
    # one crank reached from several starts (or its antipode) is one solution
    # (two cranks are one when they differ by 1e-6 of their arcs: near the planar limit all
    # of them lie within a small cap, and only their own size measures them)
    keep = []
    for error, u, w in sorted(found, key=lambda f: f[0]):
        if not any(min(np.linalg.norm(u - k * a) + np.linalg.norm(w - k * b) for k in (1.0, -1.0))
                   <= 1e-6 * (arc_between(u, w) + arc_between(a, b)) for a, b, _ in keep):
            keep.append((u, w, error))
    # complex solutions come in pairs: an odd count means two solutions have merged at one
    # kept crank (the one where the equations are nearest singular); they are two real
    # solutions listed once (`n_double`), or a complex pair, not listed
    n_double = 0
    if len(keep) % 2:
        k = min(range(len(keep)), key=lambda i: _conditioning(K0, keep[i][0], keep[i][1]))
        if _pair_is_real(K0, keep[k][0], keep[k][1]):
            n_double = 1
        else:
            del keep[k]
    n_complex = 6 - len(keep) - n_double
    # a crank and its antipode are one; near the planar limit each is listed on the side of
    # the cap (as its planar start was), so that the cranks of one design lie together
    cap = _cap_centre(K0)
    dyads, worst = [], 0.0
    for u, w, error in keep:
        if cap is not None and w @ cap < 0.0:
            u, w = -u, -w
        z = R[0].T @ w
        worst = max(worst, float(np.max(np.abs(np.einsum("i,jik,k->j", u, K, w)))))
        dyads.append(make_dyad(z, w, u, "R", R[0]))
    dyads.sort(key=lambda k: float(k.arc))
    return SphericalBurmesterPoints(tuple(dyads), int(n_complex), worst, sextic, Pa, n_double)


def _polished(R, K, K0, u0, w0, close=False):
    """The crank polished from the start (u0, w0): the error (`_dyad_error`), u and w.

    The cosine form (4) is tried first, then the chord form (`_polish_chords`) from its end
    and from the start; the best of the three is kept (the chord form is the better one
    near the planar limit, where the cosine form may also wander from the start). A start
    known to be `close` to its crank (a planar start) is polished in the chord form only,
    by steps shorter than a tenth of its arc: near the planar limit the cranks lie within
    a cap of the size of the arcs, and a longer step may land on another one.
    """
    if close:
        u, w = _polish_chords(K0, u0, w0, limit=0.1 * np.linalg.norm(u0 - w0))
        return _dyad_error(R, u, w), (u if u @ w >= 0.0 else -u), w
    u, w = _polish(K, u0, w0)
    u = u if u @ w >= 0.0 else -u
    tries = [(_dyad_error(R, u, w), u, w)]
    for start in ((u, w), (u0, w0)):
        if tries[-1][0] <= _ROUNDING:
            break
        u_, w_ = _polish_chords(K0, *start)
        tries.append((_dyad_error(R, u_, w_), u_ if u_ @ w_ >= 0.0 else -u_, w_))
    return min(tries, key=lambda t: t[0])


def _cap_centre(K0):
    """The mean of the poles of the displacements ``I + K0_j`` when they lie within a cap
    of 0.1 rad about it (near the planar limit), else None."""
    axes, angles = _axis_angle(K0)
    axes = axes * np.where(axes @ axes[int(np.argmax(angles))] < 0.0, -1.0, 1.0)[:, None]
    c = np.sum(axes, axis=0)
    if not (np.all(np.isfinite(c)) and np.linalg.norm(c) > 0.0):
        return None
    c /= np.linalg.norm(c)
    return c if np.max(np.linalg.norm(axes - c, axis=1)) <= 0.1 else None


def _planar_starts(K0):
    """Starting cranks (u, w) from the planar task that the orientations approach.

    When the poles of the displacements ``I + K0_j`` lie within a small cap about their
    mean c, the displacements act near c as planar ones in the gnomonic chart
    ``p -> (p . e1, p . e2) / (p . c)``: displacement j turns by the angle it gives e1 and
    moves c to ``c + K0_j c``. The planar Burmester cranks of those poses, taken back onto
    the sphere, are within the square of the cap's size of the spherical ones. None when
    the poles are spread (no planar limit near) or the planar task has no finite crank.
    """
    from mech.planar.synthesis import burmester as planar_burmester

    c = _cap_centre(K0)
    if c is None:
        return []
    e1, e2 = _basis(c)
    moved = K0 @ c                                          # D_j c - c, small
    d = np.r_[0.0, (moved @ e1 + 1j * (moved @ e2)) / (1.0 + moved @ c)]
    turned = e1 + K0 @ e1                                   # D_j e1
    theta = np.r_[0.0, np.arctan2(turned @ e2, turned @ e1)]
    try:
        planar = planar_burmester(theta, d)
    except ValueError:
        return []
    out = []
    for k in planar.dyads:
        z, a = complex(k.moving_pivot), complex(k.centre_point)
        w = c + z.real * e1 + z.imag * e2
        u = c + a.real * e1 + a.imag * e2
        out.append((u / np.linalg.norm(u), w / np.linalg.norm(w)))
    return out


def _pencil_resultant(Ma, Mb, P):
    """Coefficients (x^0 .. x^8, x = exp(2j phi)) of the resultant (9) of the cubics
    det[Ma_k w] and det[Mb_k w] on great circles through their common point P, with e1, e2."""
    e1, e2 = _basis(P)
    phi = np.arange(16) * (np.pi / 16)
    v = np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2
    f1, f2, f3 = _cubic_on_circles(Ma, P, v)
    g1, g2, g3 = _cubic_on_circles(Mb, P, v)
    rho = (f1 * g3 - f3 * g1) ** 2 - (f1 * g2 - f2 * g1) * (f2 * g3 - f3 * g2)
    spectrum = np.fft.fft(rho) / 16.0
    return np.array([spectrum[m % 16] for m in range(-4, 5)]), e1, e2


def _common_point(Ma, Mb, P, e1, e2, x):
    """The common point of the two cubics on the great circle through P at x = exp(2j phi)."""
    ph = 0.5 * np.angle(x)
    vv = np.cos(ph) * e1 + np.sin(ph) * e2
    (h1,), (h2,), (h3,) = _cubic_on_circles(Ma, P, vv[None])
    (k1,), (k2,), (k3,) = _cubic_on_circles(Mb, P, vv[None])
    w = (h2 * k3 - h3 * k2) * P - (h1 * k3 - h3 * k1) * vv
    size = np.linalg.norm(w)
    # both coefficients vanish (orientations 1e-200 apart): no point here; P is a start that
    # verification refuses, as any other wrong one
    return w / size if size > 0.0 else P


def slider_dyads(R, *, imag_tol=1e-7):
    """Every spherical slider through four orientations (§3.5): up to six slider points.

    A slider point's four positions lie on one great circle, so it lies on the slider-point
    cubics (7) of orientations (1, 2, 3) and (1, 2, 4). The two cubics meet in nine points;
    three are the real pole P_12 and the two complex fixed directions of D_21 (where w and
    D_21 w are parallel) and solve nothing. On great circles through P_12 the resultant (9)
    has the complex directions as its roots x = 0 and x = infinity; what is left is again
    a sextic, whose roots on the unit circle give the real slider points.

    Parameters
    ----------
    R : array_like, shape (4, 3, 3)
        Orientations.
    imag_tol : float, optional
        A root x of the sextic is real when, moved onto the unit circle and polished, it
        gives a slider whose four positions lie on its guide to this times the largest
        distance the point moves (verified, as in `burmester`); at least 0.

    Returns
    -------
    tuple of SphericalDyad
        The real slider dyads (``centre_point`` the guide's pole, ``arc`` pi/2), each
        polished so that its four positions lie on the guide to rounding.

    Raises
    ------
    ValueError
        For a wrong number of orientations, bad input, two orientations the same, or a
        negative or non-finite `imag_tol`.

    Notes
    -----
    Eqs. (5), (7) and (9) of :ref:`deriv-spherical-guidance`. With a crank from
    `circle_point_curve` each slider makes a crank-slider for four orientations
    (`guidance_slider_crank`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import slider_dyads, rotation_matrix
    >>> R = np.stack([rotation_matrix(a, t) for a, t in
    ...               [([0, 0, 1], 0.0), ([0.2, 0.1, 1], 0.5), ([-0.3, 0.2, 1], 1.0), ([0.1, -0.4, 1], 1.4)]])
    >>> found = slider_dyads(R)
    >>> all(abs(np.linalg.det(np.stack([R[j] @ k.circle_point for j in (0, 1, 2)]))) < 1e-13 for k in found)
    True
    """
    R = orientation_set("R", R, (4,))
    imag_tol = nonnegative_number("imag_tol", imag_tol)
    K = _parts(R[0], R[1:])
    if not np.any(K[0] != 0.0):
        raise ValueError("Expected orientations 1 and 2 of `R` to differ, got equal ones")
    P = _axis_angle(K[0])[0]
    Ma, Mb = [np.eye(3), K[0], K[1]], [np.eye(3), K[0], K[2]]
    coef, e1, e2 = _pencil_resultant(Ma, Mb, P)
    top = np.max(np.abs(coef))
    if not top > 0.0:
        raise ValueError("Expected four orientations with finitely many slider points, got `R` whose "
                         "slider cubics share a whole curve")
    sextic = (coef / top)[1:8]                     # the roots x = 0 and infinity are the complex axes of D_21
    roots = np.roots(np.trim_zeros(sextic[::-1], "f")) if np.any(sextic[1:] != 0) else np.array([])
    D = np.stack([np.eye(3)] + [np.eye(3) + Kj for Kj in K])
    found = []
    for x in roots:
        if not abs(abs(x) - 1.0) <= _DRIFT:
            continue
        # as in `burmester`: the root moved onto the unit circle, polished, and verified
        w = _common_point(Ma, Mb, P, e1, e2, x / abs(x) if abs(x) > 0 else 1.0)
        rows = np.stack([w, w + K[0] @ w, w + K[1] @ w, w + K[2] @ w])
        n = _null(rows)
        # polish: w on the guide at all four orientations (Newton on n^T D_j w = 0, |n| = |w| = 1)
        n, w = _polish(D, n, w)
        W = D @ w
        moved = max(float(np.max(np.linalg.norm(W - W[k], axis=1))) for k in range(4))
        error = float(np.max(np.abs(W @ n))) / moved if moved > 0 and np.all(np.isfinite(W @ n)) else np.inf
        t = w - (w @ P) * P
        drift = abs(x - np.exp(2j * np.arctan2(t @ e2, t @ e1)))
        if error <= imag_tol and drift <= _DRIFT:
            found.append((n, w, moved, drift))
    keep = single_roots([f[:3] for f in found], [f[3] for f in found],
                        lambda a, b: min(np.linalg.norm(a[1] - k * b[1]) for k in (1.0, -1.0))
                        <= 1e-6 * (a[2] + b[2]))
    dyads = []
    for n, w, _, _ in (found[k] for k in keep):
        dyads.append(make_dyad(R[0].T @ w, w, n, "R", R[0]))
    return tuple(dyads)
