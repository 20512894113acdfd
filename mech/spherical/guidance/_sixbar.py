"""Rigid-body guidance by spherical six-bars (the spherical monograph, chapter 4): the
orientation of the guided link as the input turns, and the exact design of a Watt-2 six-bar
for up to five orientations with prescribed input angles by kinematic inversion.

In the four six-bars of `mech.spherical.stephenson1` ... `watt2` the guided link is the
link EG of the second dyad (it carries the coupler point P): the floating link that is not
part of the driving four-bar ABCD. Derivation: :ref:`deriv-spherical-guidance-sixbar`.
"""

from dataclasses import dataclass

import numpy as np

from mech._validate import InputTypeError, _show, finite_array, integer, nonnegative_number
from mech.spherical._rigid_body import angle_at, rotate_about
from mech.spherical.guidance._burmester import burmester
from mech.spherical.guidance._dyads import SphericalDyad, arc_between, dyad_for_circle_point
from mech.spherical.guidance._fourbar import _orientation, _rotation_gap, guidance_fourbars
from mech.spherical.guidance._orientations import orientation_set
from mech.spherical.linkage._linkage import SphericalLinkage

__all__ = ["sixbar_orientations", "SphericalGuidanceSixBar", "guidance_watt2"]

_TWO_PI = 2.0 * np.pi


def _frame(p, q):
    t = q - np.sum(p * q, axis=-1, keepdims=True) * p
    t = t / np.linalg.norm(t, axis=-1, keepdims=True)
    return np.stack([p, t, np.cross(p, t)], axis=-1)


def sixbar_orientations(linkage, theta):
    """Orientation of the guided link EG of a spherical six-bar at the input angles `theta`.

    The guided link of `stephenson1`, `stephenson2`, `watt1` and `watt2` (and of the
    designs of `guidance_watt2`) is the link EG of the second dyad. Its orientation is the
    right-handed frame ``[E, t, E x t]`` with ``t`` the unit tangent at E of the great
    circle E -> G, eq. (1) of :ref:`deriv-spherical-guidance-sixbar`; two orientations
    differ by the rotation ``R_k @ R_j.T`` whatever body frame is chosen.

    Parameters
    ----------
    linkage : SphericalLinkage
        A linkage with points named E and G (the six-bars of `mech.spherical`).
    theta : array_like, shape (...)
        Input angles, radians.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Proper rotations; NaN where the linkage cannot assemble.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import sixbar_orientations, watt1
    >>> lk = watt1(0.3, 0.9, 0.7, 1.0, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4))
    >>> R = sixbar_orientations(lk, [0.0, 1.0])
    >>> bool(np.allclose(R[1] @ R[1].T, np.eye(3))), round(float(np.linalg.det(R[0])), 12)
    (True, 1.0)
    """
    if not isinstance(linkage, SphericalLinkage):
        raise InputTypeError(f"Expected `linkage` to be a SphericalLinkage, got {_show(linkage)}")
    missing = [p for p in ("E", "G") if p not in linkage.points]
    if missing:
        raise ValueError(f"Expected `linkage` with points E and G (the guided link EG), got points {linkage.points!r}")
    theta = finite_array("theta", theta)
    pose = linkage.solve(theta)
    with np.errstate(invalid="ignore"):
        return _frame(pose.points["E"], pose.points["G"])


@dataclass(frozen=True)
class SphericalGuidanceSixBar:
    """One Watt-2 guidance six-bar designed by `guidance_watt2`, with the analysis that checks it.

    Attributes
    ----------
    linkage : SphericalLinkage
        Ground points A, D, F; crank AB (the input); dyad B-C-D (links BC, DC); E on the
        rocker DC; dyad E-G-F (links EG, FG); the guided link is EG.
    input_offset : float
        The linkage's input angle is ``theta_j + input_offset`` at orientation j (its
        angle is measured at A from the great circle A -> D).
    points : dict of str -> ndarray, shape (3,)
        A, B, C, D, E, F, G at the first orientation.
    rocker_angles : ndarray, shape (n,)
        Rotation of the rocker DCE about D from the first orientation, radians.
    second_stage : SphericalGuidanceFourBar
        The guidance four-bar D-E-G-F of the orientations (driven by DE).
    first_stage : SphericalDyad
        The dyad B-C of the crank's rotations relative to the rocker (circle point B,
        centre point C in the rocker's first position).
    pose_error : float
        Largest angle (radians) between the orientation of EG that the linkage reaches at
        the prescribed input angle and the task's, by analysis with `SphericalLinkage`.
    in_order : bool
        The linkage assembles at every input from the first prescribed angle to the last
        (on its two fixed branches), so it meets the orientations in order.
    passes : bool
        ``in_order`` and ``pose_error <= rtol``.
    """

    linkage: SphericalLinkage
    input_offset: float
    points: dict
    rocker_angles: np.ndarray
    second_stage: object
    first_stage: SphericalDyad
    pose_error: float
    in_order: bool
    passes: bool

    def guided_orientations(self, theta):
        """Orientation R of the guided link EG (task frame) at task input angles `theta`."""
        theta = finite_array("theta", theta)
        pose = self.linkage.solve(theta + self.input_offset)
        z = self.second_stage
        zE = np.asarray(z.input_dyad.circle_point, float)
        zG = np.asarray(z.output_dyad.circle_point, float)
        with np.errstate(invalid="ignore"):
            return _orientation(pose.points["E"], pose.points["G"], zE, zG)


def _rocker_angles(D, E):
    """Signed rotation about D carrying E[0] to each E[j], eq. (3)."""
    return np.array([float(angle_at(D, E[0], e)) for e in E])


def _relative(A, D, theta, phi):
    """The crank's rotations relative to the rocker, eq. (4): S_j = Q_j^T K_j."""
    S = []
    for t, p in zip(theta - theta[0], phi):
        K = rotate_about(np.eye(3), A, t).T          # columns: images of the axes
        Q = rotate_about(np.eye(3), D, p).T
        S.append(Q.T @ K)
    return np.array(S)


def _build(A, D, F, B, C, E, G, branches=None):
    if branches is None:
        branches = (1 if np.linalg.det(np.array([B, D, C])) > 0 else -1,
                    1 if np.linalg.det(np.array([E, F, G])) > 0 else -1)
    lk = (SphericalLinkage({"A": A, "D": D, "F": F})
          .crank("AB", pivot="A", tip="B", arc=float(arc_between(A, B)), reference="D")
          .rrr(("BC", "DC"), pins=("B", "D"), joint="C",
               arcs=(float(arc_between(B, C)), float(arc_between(D, C))),
               branch=branches[0])
          .point("E", link="DC", at=(float(arc_between(D, E)), float(angle_at(D, C, E))))
          .rrr(("EG", "FG"), pins=("E", "F"), joint="G",
               arcs=(float(arc_between(E, G)), float(arc_between(F, G))),
               branch=branches[1]))
    return lk, float(angle_at(A, D, B))


def _check(R, theta, stage2, stage1, A, rtol, sweep):
    D = np.asarray(stage2.input_dyad.centre_point, float)
    F = np.asarray(stage2.output_dyad.centre_point, float)
    E = np.asarray(stage2.input_dyad.moving_pivot, float)
    G = np.asarray(stage2.output_dyad.moving_pivot, float)
    B = np.asarray(stage1.moving_pivot, float)
    C = np.asarray(stage1.centre_point, float)
    # the trivial dyad of the relative rotations is the crank's own axis (B = +-A, C = +-D):
    # no linkage; nor is a joint on a pivot's axis
    for p, q in ((A, B), (D, C), (D, E), (F, G), (B, C), (E, G), (A, D), (D, F), (A, F)):
        if np.linalg.norm(np.cross(p, q)) < 1e-6:
            return None
    try:
        lk, offset = _build(A, D, F, B, C, E, G)
    except ValueError:
        return None
    offset -= float(theta[0])
    Ej = np.einsum("nij,j->ni", R, stage2.input_dyad.circle_point)
    phi = _rocker_angles(D, Ej)
    sw = np.linspace(theta[0], theta[-1], sweep) + offset
    in_order = bool(lk.solve(sw).assembled.all())
    pose = lk.solve(theta + offset)
    zE = np.asarray(stage2.input_dyad.circle_point, float)
    zG = np.asarray(stage2.output_dyad.circle_point, float)
    with np.errstate(invalid="ignore"):
        got = _orientation(pose.points["E"], pose.points["G"], zE, zG)
    err = _rotation_gap(got, R)
    err = float(np.max(err)) if np.all(np.isfinite(err)) else float("inf")
    pts = {"A": A, "B": B, "C": C, "D": D, "E": E, "F": F, "G": G}
    return SphericalGuidanceSixBar(lk, offset, pts, phi, stage2, stage1, err, in_order,
                                   in_order and err <= rtol)


def _exact_task(R, theta, crank_pivot, rtol, sweep):
    """The checked arguments of an exact six-bar design: 2 to 5 orientations, one increasing
    input angle each within a turn, the unit crank axis, the tolerance and the sweep count."""
    R = orientation_set("R", R, (2, 3, 4, 5))
    n = R.shape[0]
    theta = finite_array("theta", theta)
    if theta.shape != (n,):
        raise ValueError(f"Expected `theta` of shape ({n},) (one input angle per orientation), got shape {theta.shape}")
    if not (np.all(np.diff(theta) > 0) and theta[-1] - theta[0] < _TWO_PI):
        raise ValueError(f"Expected `theta` strictly increasing and spanning less than a turn, got {theta.tolist()!r}")
    A = finite_array("crank_pivot", crank_pivot)
    if A.shape != (3,) or not np.any(A != 0.0):
        raise ValueError(f"Expected `crank_pivot` a non-zero 3-vector, got {_show(crank_pivot)}")
    A = A / np.max(np.abs(A))                  # only its direction counts: 1e-200 and 1e200 too
    A = A / np.linalg.norm(A)
    rtol = nonnegative_number("rtol", rtol)
    sweep = integer("sweep", sweep, minimum=2)
    return R, n, theta, A, rtol, sweep


def guidance_watt2(R, theta, crank_pivot, *, dyads=None, crank_tip=None, rtol=1e-9, sweep=721):
    """Watt-2 spherical six-bars guiding a body through orientations at prescribed input angles.

    Kinematic inversion, :ref:`deriv-spherical-guidance-sixbar`: (i) the guided link EG and
    the rocker DE with the link FG form a guidance four-bar D-E-G-F of the orientations
    (`guidance_fourbars`), which fixes the rocker's rotations phi_j about D; (ii) seen
    from the rocker, the crank about `crank_pivot` A turns by the rotations
    S_j = Q(D, phi_j)^T K(A, theta_j - theta_1), eq. (4), and the dyad B-C is a guidance
    dyad of these relative rotations (the Burmester dyads for five, `dyad_for_circle_point`
    for three or fewer). Every pairing is built as a `SphericalLinkage` and checked by
    analysis.

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations of the guided body, n = 3 or 5 (or 2).
    theta : array_like, shape (n,)
        Prescribed input angles, strictly increasing, spanning less than a turn.
    crank_pivot : array_like, shape (3,)
        The fixed axis A of the input crank (a free choice of the design).
    dyads : sequence of SphericalDyad, optional
        Guidance dyads of `R` to pair into the second stage; default the Burmester dyads
        (five orientations only).
    crank_tip : array_like, shape (3,), optional
        For fewer than five orientations: the crank's moving axis B at the first
        orientation (the circle point of the first stage).
    rtol : float, optional
        Largest accepted orientation error, radians.
    sweep : int, optional
        Inputs sampled from the first prescribed angle to the last for the order check.

    Returns
    -------
    list of SphericalGuidanceSixBar
        Every design found, the passing ones first, then by orientation error.

    Examples
    --------
    Five orientations of the link EG of a Watt-2 six-bar at five input angles; the design
    from the same crank axis finds it again among others, each reaching the orientations:

    >>> import numpy as np
    >>> from mech.spherical import guidance_watt2, sixbar_orientations, watt2
    >>> lk = watt2(0.3, 0.9, 0.7, 1.0, E=(0.3, 0.5), F=(1.4, 0.4), arcs=(0.6, 0.5), coupler=(0.3, 0.4))
    >>> theta = np.array([0.2, 0.7, 1.3, 1.9, 2.6])
    >>> designs = guidance_watt2(sixbar_orientations(lk, theta), theta, [0.0, 0.0, 1.0])
    >>> best = [d for d in designs if d.passes]
    >>> len(best) > 0, max(d.pose_error for d in best) < 1e-9
    (True, True)
    """
    R, n, theta, A, rtol, sweep = _exact_task(R, theta, crank_pivot, rtol, sweep)
    if n == 4:
        raise ValueError("Expected 2, 3 or 5 orientations in `R` (four need a point of the circle-point cubic "
                         "for the first stage, not offered here), got 4")
    if crank_tip is not None:
        B1 = finite_array("crank_tip", crank_tip)
        if B1.shape != (3,) or not np.linalg.norm(B1) > 0:
            raise ValueError(f"Expected `crank_tip` a non-zero 3-vector, got {_show(crank_tip)}")
        B1 = B1 / np.linalg.norm(B1)
    elif n < 5:
        raise ValueError(f"Expected `crank_tip` for {n} orientations, got None")
    # the rocker DE need not turn one way (the first stage drives it), so every pairing is
    # kept whose coupler reaches the orientations; the six-bar's own analysis decides
    second = [c for c in guidance_fourbars(R, dyads, rtol=rtol).candidates if c.pose_error <= 1e-6]
    found = []
    for stage2 in second:
        D = np.asarray(stage2.input_dyad.centre_point, float)
        Ej = np.einsum("nij,j->ni", R, stage2.input_dyad.circle_point)
        phi = _rocker_angles(D, Ej)
        S = _relative(A, D, theta, phi)
        try:
            firsts = burmester(S).dyads if n == 5 else (dyad_for_circle_point(S, B1),)
        except ValueError:
            continue
        for stage1 in firsts:
            made = _check(R, theta, stage2, stage1, A, rtol, sweep)
            if made is not None:
                found.append(made)
    found.sort(key=lambda s: (not s.passes, s.pose_error))
    return found
