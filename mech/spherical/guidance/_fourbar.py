"""Spherical four-bars and crank-sliders built from guidance dyads, each proved by analysis
with `SphericalFourBar` (the spherical monograph, §3.2, §3.3 and §3.6).
"""

from dataclasses import dataclass

import numpy as np

from mech._validate import InputTypeError, _show, finite_array, nonnegative_number
# _motion: the arc BD of a spherical four-bar, like the planar diagonal, is extreme at input 0 and pi
from mech._driving import input_travel as _motion
from mech.planar.synthesis._guidance_fourbar import GuidanceSynthesis
from mech.spherical._fourbar import SphericalFourBar
from mech.spherical._rigid_body import angle_at
from mech.spherical._types import classify
from mech.spherical.guidance._burmester import burmester
from mech.spherical.guidance._dyads import SphericalDyad, arc_between
from mech.spherical.guidance._orientations import orientation_set

__all__ = ["SphericalGuidanceFourBar", "guidance_fourbars", "guidance_slider_crank"]


@dataclass(frozen=True)
class SphericalGuidanceFourBar:
    """One candidate spherical four-bar for a guidance task, with the analysis that checks it.

    Attributes
    ----------
    linkage : SphericalFourBar
        The four-bar placed in the task's ground frame (``frame`` puts A at the input's
        centre point and D at the output's), coupler point at B.
    frame : ndarray, shape (3, 3)
        The placement rotation (the linkage's ``frame``).
    input_dyad, output_dyad : SphericalDyad
        The crank (driven) and the output dyad (a slider has the arc pi/2).
    theta_input : ndarray, shape (n,)
        Input angle at every orientation, in (-pi, pi].
    direction : int
        +1 if the input turns counter-clockwise (seen from outside at A) from orientation to
        orientation, -1 if clockwise, 0 if it does not reach them in order on one branch.
    kind : str
        Type of the linkage (`mech.spherical.classify`).
    in_order : bool
        The input, turning one way by less than a full turn, meets the orientations in the
        given order, the linkage assembles all the way, and det[B, D, C] keeps its sign at
        every orientation (one branch).
    pose_error : float
        Largest angle (radians) between a reproduced orientation and the task's.
    passes : bool
        ``in_order`` and ``pose_error <= rtol``.
    gamma_at_poses : ndarray, shape (n,)
        Transmission angle (the angle at C between the great circles C->B and C->D, folded
        into [0, pi/2]) at each orientation.
    gamma_min : float
        Smallest transmission angle over the motion from the first orientation to the last
        when `in_order`, else over the orientations only.
    """

    linkage: SphericalFourBar
    frame: np.ndarray
    input_dyad: SphericalDyad
    output_dyad: SphericalDyad
    theta_input: np.ndarray
    direction: int
    kind: str
    in_order: bool
    pose_error: float
    passes: bool
    gamma_at_poses: np.ndarray
    gamma_min: float

    def coupler_orientations(self, theta_input):
        """The coupler's orientation R (shape (..., 3, 3)) at input angles `theta_input`."""
        pose = self.linkage.solve(finite_array("theta_input", theta_input))
        return _orientation(pose.B, pose.C, self.input_dyad.circle_point, self.output_dyad.circle_point)


def _frame_of(p, q):
    """Right-handed frames [p, t, p x t] with t the direction from p toward q (shape (..., 3, 3))."""
    t = q - np.sum(p * q, axis=-1, keepdims=True) * p
    t = t / np.linalg.norm(t, axis=-1, keepdims=True)
    return np.stack([p, t, np.cross(p, t)], axis=-1)


def _orientation(B, C, zB, zC):
    """The rotation carrying the body axes zB, zC to B, C."""
    return _frame_of(B, C) @ np.swapaxes(_frame_of(np.asarray(zB), np.asarray(zC)), -1, -2)


def _rotation_gap(Ra, Rb):
    """Angle of Ra Rb^T, accurate for small angles: 2 asin(|Ra - Rb|_F / sqrt(8))."""
    return 2.0 * np.arcsin(np.minimum(1.0, np.linalg.norm(Ra - Rb, axis=(-2, -1)) / np.sqrt(8.0)))


def _transmission(B, C, D):
    g = np.abs(angle_at(C, B, D))
    return np.minimum(g, np.pi - g)


def _candidate(R, crank, rocker, rtol):
    A, D = np.asarray(crank.centre_point, float), np.asarray(rocker.centre_point, float)
    zB, zC = np.asarray(crank.circle_point, float), np.asarray(rocker.circle_point, float)
    arcs = (float(crank.arc), float(arc_between(zB, zC)), float(arc_between(np.asarray(rocker.moving_pivot),
                                                                              D)), float(arc_between(A, D)))
    if not all(np.isfinite(x) and 0.0 < x < np.pi for x in arcs):
        return None
    frame = _frame_of(A, D)[:, [1, 2, 0]]           # columns: toward D, (A x toward D), A
    B = np.einsum("nij,j->ni", R, zB)
    C = np.einsum("nij,j->ni", R, zC)
    local = B @ frame
    theta_in = np.arctan2(local[:, 1], local[:, 0])
    side = np.sign(np.sum(B * np.cross(D, C), axis=-1))
    branch = int(side[0]) if side[0] != 0 else 1
    try:
        model = SphericalFourBar(*arcs, branch=branch, frame=frame)
    except ValueError:
        return None
    pose = model.solve(theta_in)
    if np.all(pose.valid):
        pose_error = float(np.max(_rotation_gap(_orientation(pose.B, pose.C, zB, zC), R)))
    else:
        pose_error = float("inf")
    direction, critical = _motion(model, theta_in)
    in_order = bool(direction != 0 and np.all(side == side[0]))
    gamma_at = _transmission(B, C, D)
    if in_order:
        crit = model.solve(critical)
        gamma_min = float(min(np.min(_transmission(crit.B, crit.C, D)), np.min(gamma_at)))
    else:
        gamma_min = float(np.min(gamma_at))
    try:
        kind = classify(*arcs).kind
    except ValueError:
        kind = "unknown"
    return SphericalGuidanceFourBar(
        linkage=model, frame=frame, input_dyad=crank, output_dyad=rocker, theta_input=theta_in,
        direction=direction if in_order else 0, kind=kind, in_order=in_order, pose_error=pose_error,
        passes=bool(in_order and pose_error <= rtol), gamma_at_poses=gamma_at, gamma_min=gamma_min)


def _check_dyads(dyads, names=None):
    """Check a list of dyads; `names` gives each its own argument name (else `dyads` at index k)."""
    if not isinstance(dyads, (list, tuple)):
        raise InputTypeError(f"Expected `dyads` to be a list or tuple of SphericalDyad records, got {_show(dyads)}")
    for k, dyad in enumerate(dyads):
        where = f"`{names[k]}`" if names else "`dyads`"
        at = "" if names else f" at index {k}"
        if not isinstance(dyad, SphericalDyad) or np.shape(dyad.circle_point) != (3,):
            raise ValueError(f"Expected {where} of single SphericalDyad records, got {_show(dyad)}{at}")
        fields = (dyad.circle_point, dyad.moving_pivot, dyad.centre_point, dyad.arc)
        if not all(np.all(np.isfinite(np.asarray(f, dtype=float))) for f in fields):
            raise ValueError(f"Expected {where} with finite fields, got {dyad!r}{at}")
    return tuple(dyads)


def guidance_fourbars(R, dyads=None, *, rtol=1e-9):
    """Every spherical four-bar made of two guidance dyads, each checked by analysis.

    Each ordered pair of distinct dyads (input, output) gives a four-bar ABCD: A and D the
    centre points, B and C the circle points. It is built as a placed `SphericalFourBar`
    and must reproduce every orientation, stay on one assembly branch, and meet the
    orientations in order as its input turns one way by less than a turn.

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations, 2 <= n <= 5.
    dyads : sequence of SphericalDyad, optional
        The dyads to pair. Default: the Burmester dyads of five orientations (`burmester`).
    rtol : float, optional
        Largest accepted orientation error, radians.

    Returns
    -------
    mech.planar.synthesis.GuidanceSynthesis
        ``dyads``, ``candidates`` (every `SphericalGuidanceFourBar`, both choices of input)
        and ``passing``, as for the planar `mech.planar.synthesis.guidance_fourbars`.

    Raises
    ------
    ValueError
        For bad orientations, no `dyads` with fewer than five orientations, or fewer than
        two dyads given (`InputTypeError` when `dyads` is not a list or tuple).

    Notes
    -----
    The branch is the sign of det[B, D, C] at the first orientation; a candidate whose sign
    changes between orientations has a branch defect and fails. The input's path is
    checked at its ends and at the input angles 0 and pi inside it, where the arc BD is
    extreme; the transmission angle is extreme there too. :ref:`deriv-spherical-guidance`.

    Examples
    --------
    Example 2-15 on a sphere of radius 1000 (arcs in milliradians; the planar crank-rocker
    has 108.757, 191.146, 186.698, 188.847):

    >>> import numpy as np
    >>> from mech.spherical import guidance_fourbars, planar_orientations
    >>> P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j]
    >>> R = planar_orientations(np.radians([0.0, 8.88, 22.1, 63.68, -3.0]), P, 1e-3)
    >>> best = guidance_fourbars(R).passing[0]
    >>> best.kind, [round(x * 1e3, 3) for x in (best.linkage.a, best.linkage.b, best.linkage.c, best.linkage.d)]
    ('crank-rocker', [108.836, 192.038, 187.013, 188.216])
    >>> best.pose_error < 1e-12
    True
    """
    R = orientation_set("R", R, (2, 3, 4, 5))
    rtol = nonnegative_number("rtol", rtol)
    if dyads is None:
        if R.shape[0] != 5:
            raise ValueError(f"Expected `dyads` for {R.shape[0]} orientations (only five fix them), got None")
        dyads = burmester(R).dyads
    else:
        dyads = _check_dyads(dyads)
        if len(dyads) < 2:
            raise ValueError(f"Expected `dyads` to hold at least two SphericalDyad records, got {len(dyads)}")
    candidates = []
    for i, crank in enumerate(dyads):
        for j, rocker in enumerate(dyads):
            if i != j:
                found = _candidate(R, crank, rocker, rtol)
                if found is not None:
                    candidates.append(found)
    return GuidanceSynthesis(tuple(dyads), tuple(candidates), tuple(c for c in candidates if c.passes))


def guidance_slider_crank(R, crank, slider, *, rtol=1e-9):
    """The spherical crank-slider of a crank and a slider dyad, checked by analysis (§3.3).

    A spherical slider is the crank of arc pi/2 (its axis stays on the great circle whose
    pole is its centre point), so the crank-slider is the spherical four-bar with output
    arc c = pi/2, moved by `SphericalFourBar` as any other.

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations, 2 <= n <= 5.
    crank, slider : SphericalDyad
        The driven crank and the slider (from `slider_dyad_for_point` or
        `slider_point_curve`).
    rtol : float, optional
        Largest accepted orientation error, radians.

    Returns
    -------
    SphericalGuidanceFourBar or None
        None if the two dyads make no four-bar (an arc of 0 or pi between them).

    Raises
    ------
    ValueError
        For bad orientations or dyads, or a `slider` whose arc is not pi/2.

    Notes
    -----
    Eq. (5) of :ref:`deriv-spherical-guidance`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import (guidance_slider_crank, dyad_for_circle_point, slider_point_curve,
    ...                             rotation_matrix)
    >>> R = np.stack([np.eye(3), rotation_matrix([0.2, 0.1, 1], 0.5), rotation_matrix([-0.3, 0.2, 1], 1.0)])
    >>> curve = slider_point_curve(R, samples=12)
    >>> slider = curve.dyad(*np.argwhere(curve.valid)[0])
    >>> design = guidance_slider_crank(R, dyad_for_circle_point(R, [0.3, 0.2, 0.93]), slider)
    >>> design.pose_error < 1e-12, round(design.linkage.c, 12)
    (True, 1.570796326795)
    """
    R = orientation_set("R", R, (2, 3, 4, 5))
    rtol = nonnegative_number("rtol", rtol)
    crank, slider = _check_dyads([crank, slider], names=("crank", "slider"))
    if abs(float(slider.arc) - np.pi / 2) > 1e-9:
        raise ValueError(f"Expected `slider` of arc pi/2 (a slider dyad), got arc {float(slider.arc)!r}")
    return _candidate(R, crank, slider, rtol)
