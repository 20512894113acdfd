"""Rigid-body guidance by the Stephenson-3 spherical six-bar with prescribed input angles, by
the constant-length condition (the spherical monograph, chapter 4).

The guided link CGH hangs from the input crank ABE by the binary links BC and EG and from the
ground by DH (`mech.spherical.stephenson3`). With the crank's axis A chosen, the three binary
links are three independent constant-arc conditions:

- D-H: the fixed axis D and the body axis h keep their arc over the orientations R_j;
- B-C and E-G: seen from the crank, the body turns by S_j = K(A, theta_j - theta_1)^T R_j, and
  the crank's axes B, E keep their arcs to the body axes c, g over the S_j.

Each is solved for its two axes and its arc (five unknowns) from the residuals of the
constant arc (one per orientation): a square system for five orientations (exact), a least
squares problem beyond. SciPy is imported lazily. Derivation:
:ref:`deriv-spherical-guidance-sixbar`, eqs. (15)-(16).
"""

from dataclasses import dataclass

import numpy as np

from mech._validate import InputTypeError, _show, finite_array, nonnegative_number
from mech.spherical._rigid_body import rotate_about
from mech.spherical.guidance._burmester import burmester
from mech.spherical.guidance._dyads import SphericalDyad, arc_between
from mech.spherical.guidance._fourbar import _rotation_gap
from mech.spherical.guidance._optimal import _point, _tangents
from mech.spherical.guidance._orientations import orientation_set
from mech.spherical.linkage._stephenson3 import SphericalStephenson3

__all__ = ["SphericalGuidanceStephenson3", "guidance_stephenson3"]


@dataclass(frozen=True)
class SphericalGuidanceStephenson3:
    """One Stephenson-3 guidance six-bar found by `guidance_stephenson3`, checked by analysis.

    Attributes
    ----------
    linkage : SphericalStephenson3
        Assembled at the first orientation: ground A, D; crank ABE; guided link CGH.
    input_offset : float
        The linkage's input angle is ``theta_j + input_offset`` at orientation j.
    ground_dyad, crank_dyads : SphericalDyad, (SphericalDyad, SphericalDyad)
        D-H in the ground; B-C and E-G in the crank's frame at the first orientation (centre
        points B and E, circle points c and g in body coordinates).
    arc_residual : float
        Largest change (radians) of a binary link's arc over the orientations when the body
        is placed exactly at them: the constant-length residual (0 for an exact design).
    errors : ndarray, shape (n,)
        Orientation error (radians) of the guided link at each prescribed input, by analysis
        (`SphericalStephenson3`, continued from the first orientation).
    pose_error : float
        The largest of `errors`.
    in_order : bool
        The analysis reaches every prescribed input from the first without a dead point, so
        on one branch and in order.
    passes : bool
        ``in_order`` and ``pose_error <= rtol``.
    first_orientation : ndarray, shape (3, 3)
        The guided body's orientation in the assembly at the first input: R_1 for an exact
        design; beyond five orientations the nearest orientation where the dyads' mean arcs
        close (the body is turned from R_1 to assemble the linkage).
    """

    linkage: SphericalStephenson3
    input_offset: float
    ground_dyad: SphericalDyad
    crank_dyads: tuple
    arc_residual: float
    errors: np.ndarray
    pose_error: float
    in_order: bool
    passes: bool
    first_orientation: np.ndarray

    def guided_orientations(self, theta):
        """Orientation of the guided body (task frame) at task input angles `theta`.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spherical import guidance_stephenson3, stephenson3
        >>> lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
        ...                  coupler=(0.3, 0.4), mu=0.8)
        >>> theta = np.array([0.0, 0.25, 0.5, 0.75, 1.0])
        >>> R = lk.orientations(theta)
        >>> best = guidance_stephenson3(R, theta, lk.assembly["A"])[0]
        >>> float(np.abs(best.guided_orientations(theta[2]) - R[2]).max()) < 1e-9
        True
        """
        theta = finite_array("theta", theta)
        Q = self.linkage.rotations(theta + self.input_offset)
        return Q @ self.first_orientation


def _residual_dyad(S, centre, circle, T0, T1):
    """Constant-arc residuals (cosines) of the dyad centre - circle over the rotations S."""
    def f(x):
        u = _point(centre, T0, x[0:2])
        z = _point(circle, T1, x[2:4])
        return np.einsum("i,nij,j->n", u, S, z) - x[4]
    return f


def _solve_dyad(S, centre, circle):
    """The dyad nearest the start (centre, circle) with a constant arc over S (least squares)."""
    from scipy.optimize import least_squares

    centre = centre / np.linalg.norm(centre)
    circle = circle / np.linalg.norm(circle)
    T0, T1 = _tangents(centre), _tangents(circle)
    f = _residual_dyad(S, centre, circle, T0, T1)
    x0 = np.array([0.0, 0.0, 0.0, 0.0, float(np.mean(np.einsum("i,nij,j->n", centre, S, circle)))])
    # five unknowns: with five rotations the system is square (an exact dyad), beyond it
    # is the least-squares problem of the constant-length condition
    sol = least_squares(f, x0, method="lm", xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=400)
    u = _point(centre, T0, sol.x[0:2])
    z = _point(circle, T1, sol.x[2:4])
    moved = np.einsum("nij,j->ni", S, z)
    arcs = arc_between(u, moved)
    if u @ moved[0] < 0.0:                         # the centre's end nearer the moving axis
        u = -u
        arcs = np.pi - arcs
    return SphericalDyad(z, moved[0], u, float(np.mean(arcs))), float(np.ptp(arcs))


def _distinct(dyads, tol=1e-7):
    out = []
    for d, r in dyads:
        if all(np.linalg.norm(d.circle_point - e.circle_point) > tol or
               np.linalg.norm(d.centre_point - e.centre_point) > tol for e, _ in out):
            out.append((d, r))
    return out


def _design(R, theta, A, ground, crank, rtol):
    D, h = ground[0].centre_point, ground[0].circle_point
    (d1, r1), (d2, r2) = crank
    B, c = d1.centre_point, d1.circle_point
    E, g = d2.centre_point, d2.circle_point
    # assemble at the first input with the dyads' arcs (their means over the orientations;
    # for an exact design the arcs at every orientation): turn the body from R_1 by the
    # small rotation W that closes the three arcs (Newton, the rows of eq. (14))
    W = np.eye(3)
    target = np.cos([d1.arc, d2.arc, ground[0].arc])
    for _ in range(20):
        C, G, H = W @ R[0] @ c, W @ R[0] @ g, W @ R[0] @ h
        r = np.array([B @ C, E @ G, D @ H]) - target
        if np.max(np.abs(r)) <= 1e-15:
            break
        J = np.array([np.cross(C, B), np.cross(G, E), np.cross(H, D)])
        try:
            w = np.linalg.solve(J, -r)
        except np.linalg.LinAlgError:
            return None
        t = np.linalg.norm(w)
        if not t < 0.5:
            return None
        k = w / t if t > 0 else w
        Kx = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
        W = (np.eye(3) + np.sin(t) * Kx + (1.0 - np.cos(t)) * (Kx @ Kx)) @ W
    R1 = W @ R[0]
    pts = {"A": A, "D": D, "B": B, "E": E, "C": R1 @ c, "G": R1 @ g, "H": R1 @ h}
    for p, q in (("A", "B"), ("A", "E"), ("B", "E"), ("A", "D"), ("C", "G"), ("C", "H"), ("G", "H")):
        if np.linalg.norm(np.cross(pts[p], pts[q])) < 1e-6:
            return None
    try:
        lk = SphericalStephenson3(pts)
    except ValueError:
        return None
    offset = lk.theta0 - float(theta[0])
    # a dead point of the triad between two orientations shows as a change of the sign of
    # the determinant of eq. (14) at the exact poses: skip those without marching
    signs = []
    for j in range(R.shape[0]):
        Q = R[j] @ R1.T
        signs.append(np.sign(np.linalg.det(lk._jacobian(Q, float(theta[j] - theta[0])))))
    if len(set(signs)) > 1:
        return None
    Q = lk.rotations(theta + offset)
    got = Q @ R1
    errors = _rotation_gap(got, R)
    in_order = bool(np.all(np.isfinite(errors)))
    errors = np.where(np.isfinite(errors), errors, np.pi)
    res = max(ground[1], r1, r2)
    return SphericalGuidanceStephenson3(lk, offset, ground[0], (d1, d2), res, errors, float(errors.max()),
                                        in_order, in_order and float(errors.max()) <= rtol, R1)


def guidance_stephenson3(R, theta, crank_pivot, *, subset=None, rtol=1e-9):
    """Stephenson-3 spherical six-bars guiding a body through orientations at given input angles.

    The constant-length route of the monograph's chapter 4 (eqs. (15)-(16) of
    :ref:`deriv-spherical-guidance-sixbar`): with the crank axis A chosen, each of the three
    binary links D-H, B-C and E-G is found from the residuals of its constant arc over the
    orientations (over R_j for D-H, over the rotations S_j = K(A, theta_j - theta_1)^T R_j
    seen from the crank for B-C and E-G), five unknowns each: exact for five orientations,
    least squares beyond. The starts are the Burmester dyads of five of the orientations
    (`burmester`). Every ground dyad is paired with every two crank dyads, assembled at the
    first orientation as a `SphericalStephenson3` and moved by analysis through the
    prescribed inputs, which measures its errors and its order.

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations of the guided body, n >= 5.
    theta : array_like, shape (n,)
        Prescribed input angles, strictly increasing, spanning less than a turn.
    crank_pivot : array_like, shape (3,)
        The fixed axis A of the input crank (a free choice of the design).
    subset : sequence of 5 int, optional
        The orientations whose Burmester dyads start the solves (default: five spread over
        the set, all of them for n = 5).
    rtol : float, optional
        The stated error: a design ``passes`` when it is in order and its largest
        orientation error is at most `rtol` radians.

    Returns
    -------
    list of SphericalGuidanceStephenson3
        Every pairing that assembles with no dead point flagged between the orientations,
        the passing ones first, then by orientation error.

    Raises
    ------
    ValueError
        For fewer than five orientations, bad input angles or a bad `subset`.

    Examples
    --------
    Five orientations of the guided link of a Stephenson-3 six-bar at five inputs; the
    design from the same crank axis finds six-bars that reach them exactly:

    >>> import numpy as np
    >>> from mech.spherical import guidance_stephenson3, stephenson3
    >>> lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
    ...                  coupler=(0.3, 0.4), mu=0.8)
    >>> theta = np.array([0.0, 0.25, 0.5, 0.75, 1.0])
    >>> designs = guidance_stephenson3(lk.orientations(theta), theta, [0.0, 0.0, 1.0])
    >>> designs[0].passes, designs[0].pose_error < 1e-9
    (True, True)
    """
    R = orientation_set("R", R, task=True)
    n = R.shape[0]
    if n < 5:
        raise ValueError(f"Expected at least 5 orientations in `R`, got {n}")
    theta = finite_array("theta", theta)
    if theta.shape != (n,):
        raise ValueError(f"Expected `theta` of shape ({n},) (one input angle per orientation), got shape {theta.shape}")
    if not (np.all(np.diff(theta) > 0) and theta[-1] - theta[0] < 2.0 * np.pi):
        raise ValueError(f"Expected `theta` strictly increasing and spanning less than a turn, got {theta.tolist()!r}")
    A = finite_array("crank_pivot", crank_pivot)
    if A.shape != (3,) or not np.any(A != 0.0):
        raise ValueError(f"Expected `crank_pivot` a non-zero 3-vector, got {_show(crank_pivot)}")
    A = A / np.max(np.abs(A))                  # only its direction counts: 1e-200 and 1e200 too
    A = A / np.linalg.norm(A)
    if subset is None:
        subset = np.unique(np.round(np.linspace(0, n - 1, 5)).astype(int))
    else:
        try:
            subset = np.asarray(subset)
        except Exception as exc:  # pragma: no cover - numpy accepts nearly anything
            raise InputTypeError(f"Expected `subset` to be five indices, got {_show(subset)}") from exc
        if (subset.shape != (5,) or subset.dtype.kind not in "iu" or len(set(subset.tolist())) != 5
                or subset.min() < 0 or subset.max() >= n):
            raise ValueError(f"Expected `subset` to be five different indices in [0, {n}), got {_show(subset)}")
    rtol = nonnegative_number("rtol", rtol)
    K = rotate_about(np.eye(3)[None], A[None, None], (theta - theta[0])[:, None]).transpose(0, 2, 1)
    S = np.einsum("nji,njk->nik", K, R)          # K_j^T R_j: the body seen from the crank
    grounds, cranks = [], []
    for target, into in ((R, grounds), (S, cranks)):
        try:
            starts = burmester(target[subset]).dyads
        except ValueError:
            starts = ()
        for d in starts:
            into.append(_solve_dyad(target, np.asarray(d.centre_point, float), np.asarray(d.circle_point, float)))
    grounds, cranks = _distinct(grounds), _distinct(cranks)
    found = []
    for gd in grounds:
        for i in range(len(cranks)):
            for k in range(i + 1, len(cranks)):
                made = _design(R, theta, A, gd, (cranks[i], cranks[k]), rtol)
                if made is not None:
                    found.append(made)
    found.sort(key=lambda s: (not s.passes, s.pose_error))
    return found
