"""Linkages built from guidance dyads, each proved by analysis.

Four-bars from pairs of RR dyads (`guidance_fourbars`, moved by `FourBar`), and the centric
slider-cranks of four poses, (2-42), whose guide passes through the crank's fixed pivot
(`centric_slider_cranks`, moved by `SliderCrank` and `Linkage`).
"""

from dataclasses import dataclass

import numpy as np

from mech._generated import displacement as _gen
from mech._driving import input_travel as _motion
from mech._geometry import wrap_angle as _wrap
from mech._validate import InputTypeError, _show, finite_array, nonnegative_number, planar_points, real_number
from mech.planar.kinematics._fourbar import FourBar
from mech.planar.kinematics._slider_crank import SliderCrank
from mech.planar.structure._grashof import grashof
from mech.planar.synthesis._displacement import pose_set
from mech.planar.synthesis._guidance import Dyad, _det_cubic, burmester
from mech.planar.synthesis._slider_guidance import (GuidanceSliderCrank, SliderDyad, _images, guidance_slider_crank,
                                                    slider_dyads)

__all__ = ["GuidanceFourBar", "GuidanceSynthesis", "guidance_fourbars", "CentricSliderCrank", "centric_slider_cranks"]

_TWO_PI = 2.0 * np.pi


@dataclass(frozen=True)
class GuidanceFourBar:
    """One candidate four-bar for a guidance task, with the analysis that checks it.

    Attributes
    ----------
    linkage : FourBar
        The four-bar in its standard frame (A = 0, D on +x), its coupler point at the body
        origin, so ``linkage.solve(theta_input).P`` are the task's translations, placed.
    origin, angle : complex, float
        Placement: a standard-frame point ``w`` is at ``origin + exp(1j*angle)*w`` in the
        task's ground frame (``origin`` is the input's centre point).
    input_dyad, output_dyad : Dyad
        The crank (driven) and the output dyad.
    theta_input : ndarray, shape (n,)
        Input angle at every precision pose (standard frame), in (-pi, pi].
    direction : int
        +1 if the input turns counter-clockwise from pose to pose, -1 if clockwise, 0 if
        neither reaches the poses in order on one branch.
    kind : str
        Grashof type of the linkage.
    in_order : bool
        The input, turning monotonically one way by less than a full turn, meets the poses
        in the given order, the linkage stays assembled all the way, and C stays on one
        side of the line B->D at every pose (one branch).
    pose_error : float
        Largest error of the reproduced poses: translation error relative to the longest
        link, or rotation error in radians, whichever is larger.
    passes : bool
        ``in_order`` and ``pose_error <= rtol``.
    gamma_at_poses : ndarray, shape (n,)
        Transmission angle at each precision pose, radians.
    gamma_min : float
        Smallest transmission angle over the motion from the first pose to the last when
        `in_order`, else over the precision poses only.
    """

    linkage: FourBar
    origin: complex
    angle: float
    input_dyad: Dyad
    output_dyad: Dyad
    theta_input: np.ndarray
    direction: int
    kind: str
    in_order: bool
    pose_error: float
    passes: bool
    gamma_at_poses: np.ndarray
    gamma_min: float

    def to_ground(self, w):
        """Map standard-frame points (complex) to the task's ground frame."""
        return self.origin + np.exp(1j * self.angle) * planar_points("w", w)

    def coupler_poses(self, theta_input):
        """The coupler's pose ``(theta, d)`` in the task frame at input angles `theta_input`."""
        pose = self.linkage.solve(finite_array("theta_input", theta_input))
        zB, zC = self.input_dyad.circle_point, self.output_dyad.circle_point
        theta = np.angle(pose.C - pose.B) + self.angle - np.angle(zC - zB)
        return np.angle(np.exp(1j * theta)), self.to_ground(pose.P)


@dataclass(frozen=True)
class GuidanceSynthesis:
    """Every four-bar made of two of the given dyads (returned by `guidance_fourbars`).

    Attributes
    ----------
    dyads : tuple of Dyad
        The dyads paired.
    candidates : tuple of GuidanceFourBar
        One per ordered pair (input, output) of distinct dyads whose lengths make a
        four-bar; both choices of input are listed.
    passing : tuple of GuidanceFourBar
        The candidates that pass every check (`GuidanceFourBar.passes`).
    """

    dyads: tuple
    candidates: tuple
    passing: tuple


def _candidate(theta, d, crank, rocker, rtol):
    """Assemble and analyse the four-bar with `crank` driven and `rocker` as output."""
    A, D = crank.centre_point, rocker.centre_point
    zB, zC = crank.circle_point, rocker.circle_point
    lengths = (crank.length, abs(zC - zB), rocker.length, abs(D - A))
    if not all(np.isfinite(x) and x > 0.0 for x in lengths):
        return None
    unit = max(lengths)
    angle = float(np.angle(D - A))
    rot = np.exp(-1j * angle)
    # the checks run on a copy scaled to a longest link of 1: angles do not change, and no
    # intermediate overflows or underflows whatever the task's unit of length
    B = rot * ((np.exp(1j * theta) * zB + (d - A)) / unit)
    C = rot * ((np.exp(1j * theta) * zC + (d - A)) / unit)
    scaled = tuple(x / unit for x in lengths)
    try:
        # FourBar rejects one link at least as long as the other three together
        probe = FourBar(*scaled)
    except ValueError:
        return None
    theta_in = np.angle(B)
    side = np.sign(np.imag(np.conj(probe.d - B) * (C - B)))
    branch = int(side[0]) if side[0] != 0 else 1
    body = -zB * np.exp(-1j * np.angle(zC - zB))
    model = FourBar(*scaled, branch=branch, coupler=(float(body.real / unit), float(body.imag / unit)))
    pose = model.solve(theta_in)
    with np.errstate(invalid="ignore"):
        placed = pose.P * np.exp(1j * angle)
        turned = np.angle(pose.C - pose.B) + angle - np.angle(zC - zB)
        err_d = np.max(np.abs(placed - (d - A) / unit))
        err_t = np.max(np.abs(_wrap(turned - theta)))
    pose_error = float(max(err_d, err_t)) if np.all(pose.valid) else float("inf")
    direction, critical = _motion(model, theta_in)
    in_order = bool(direction != 0 and np.all(side == side[0]))
    gamma_at = np.asarray(model.transmission_angle(theta_in), dtype=float)
    gamma_min = float(np.min(model.transmission_angle(critical))) if in_order else float(np.min(gamma_at))
    linkage = FourBar(*lengths, branch=branch, coupler=(float(body.real), float(body.imag)))
    return GuidanceFourBar(
        linkage=linkage, origin=complex(A), angle=angle, input_dyad=crank, output_dyad=rocker,
        theta_input=theta_in, direction=direction if in_order else 0,
        kind=grashof(*lengths).kind, in_order=in_order, pose_error=pose_error,
        passes=bool(in_order and pose_error <= rtol), gamma_at_poses=gamma_at, gamma_min=gamma_min,
    )


def guidance_fourbars(theta, d, dyads=None, *, rtol=1e-9):
    """Every four-bar made of two guidance dyads, each checked by analysis.

    Each ordered pair of distinct dyads (input, output) gives a four-bar ABCD: A and D are
    the centre points, B and C the circle points. The linkage is handed to
    `mech.planar.FourBar` and must reproduce every precision pose, stay on one assembly
    branch, and meet the poses in order as its input turns one way by less than a turn.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Pose angles, radians, 2 <= n <= 5.
    d : array_like of complex, shape (n,)
        Pose translations.
    dyads : sequence of Dyad, optional
        The dyads to pair (scalar fields). Default: the Burmester dyads of five poses
        (`burmester`).
    rtol : float, optional
        Largest accepted pose error (relative to the longest link; radians for the angle).

    Returns
    -------
    GuidanceSynthesis
        ``candidates`` (every four-bar, both choices of input) and ``passing``.

    Raises
    ------
    ValueError
        For bad poses, no `dyads` with fewer than five poses, or fewer than two `dyads`
        given (`InputTypeError` when `dyads` is not a list or tuple).

    Notes
    -----
    The branch is the side of C from the line B->D at the first pose; a candidate whose C
    changes side between poses fails (a branch defect). The input's path from the first
    pose to the last is checked at its ends and at the input angles 0 and pi inside it,
    where the diagonal BD is extreme: if the linkage assembles there it assembles all the
    way, and the transmission angle is smallest at one of those angles too. Derivation:
    :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import guidance_fourbars
    >>> P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j]
    >>> theta = np.radians([0.0, 8.88, 22.1, 63.68, -3.0])          # example 2-15
    >>> result = guidance_fourbars(theta, P)
    >>> best = result.passing[0]
    >>> best.kind, [round(x, 3) for x in (best.linkage.a, best.linkage.b, best.linkage.c, best.linkage.d)]
    ('crank-rocker', [108.757, 191.146, 186.698, 188.847])
    """
    theta, d = pose_set(theta, d, (2, 3, 4, 5))
    rtol = nonnegative_number("rtol", rtol)
    user_dyads = dyads is not None
    if dyads is None:
        if theta.size != 5:
            raise ValueError(f"Expected `dyads` for {theta.size} poses (only five fix them), got None")
        dyads = burmester(theta, d).dyads
    elif not isinstance(dyads, (list, tuple)):
        raise InputTypeError(f"Expected `dyads` to be a list or tuple of Dyad records, got {_show(dyads)}")
    dyads = tuple(dyads)
    for k, dyad in enumerate(dyads):
        if not isinstance(dyad, Dyad) or np.ndim(dyad.length) != 0:
            raise ValueError(f"Expected `dyads` of single Dyad records, got {dyad!r} at index {k}")
        fields = (dyad.circle_point, dyad.moving_pivot, dyad.centre_point, dyad.length)
        if not all(isinstance(f, (int, float, complex, np.number)) and not isinstance(f, (bool, np.bool_))
                   and np.isfinite(f) for f in fields):
            raise ValueError(f"Expected `dyads` with finite numeric fields, got {dyad!r} at index {k}")
    if len(dyads) < 2 and user_dyads:
        raise ValueError(f"Expected `dyads` to hold at least two Dyad records (a pair), got {len(dyads)}")
    candidates = []
    for i, crank in enumerate(dyads):
        for j, rocker in enumerate(dyads):
            if i != j:
                found = _candidate(theta, d, crank, rocker, rtol)
                if found is not None:
                    candidates.append(found)
    return GuidanceSynthesis(dyads, tuple(candidates), tuple(c for c in candidates if c.passes))


@dataclass(frozen=True)
class CentricSliderCrank:
    """A centric slider-crank for four poses (Fig. 2-91), proved by analysis.

    Attributes
    ----------
    slider_crank : SliderCrank
        The linkage in its standard frame: A = 0, the guide along the x axis (offset 0), on
        the branch that reproduces the poses.
    origin, angle : complex, float
        Placement: a standard-frame point ``w`` is at ``origin + exp(1j*angle)*w`` in the
        task frame; ``origin`` is A, ``angle`` the guide angle beta of A -> C_1 (the text's
        tan(beta) after (2-42)).
    crank, slider : Dyad, SliderDyad
        The crank AB and the slider dyad of the pin C.
    theta_input : ndarray, shape (4,)
        Crank angle at every pose, standard frame, in (-pi, pi].
    pose_error : float
        Largest error of the poses reproduced by `SliderCrank` (as in `GuidanceSliderCrank`).
    guidance : GuidanceSliderCrank
        The same linkage built and checked as a `Linkage` (order of the poses, mode of
        the RRP group, transmission angles).
    passes : bool
        ``guidance.passes`` and ``pose_error <= rtol``.
    """

    slider_crank: SliderCrank
    origin: complex
    angle: float
    crank: Dyad
    slider: SliderDyad
    theta_input: np.ndarray
    pose_error: float
    guidance: GuidanceSliderCrank
    passes: bool

    def to_ground(self, w):
        """Map standard-frame points (complex) to the task's ground frame."""
        return self.origin + np.exp(1j * self.angle) * planar_points("w", w)

    def coupler_poses(self, theta_input):
        """The coupler's pose ``(theta, d)`` in the task frame at crank angles `theta_input` (standard frame)."""
        sol = self.slider_crank.solve(finite_array("theta_input", theta_input))
        zB, zC = self.crank.circle_point, self.slider.slider_point
        theta = np.angle(np.exp(1j * (np.angle(sol.C - sol.B) + self.angle - np.angle(zC - zB))))
        return theta, self.to_ground(sol.B) - np.exp(1j * theta) * zB


def _centric_rows(theta, dn, A):
    """The three equations (2-40) at centre point A as rows [m_x, m_y, m_0] (linear in the circle point)."""
    m = _gen.centric_crank_rows(theta[0], dn[0].real, dn[0].imag, theta[1:], dn[1:].real, dn[1:].imag,
                                A.real, A.imag)
    return np.stack([np.broadcast_to(v, (3,)) for v in m], axis=-1)


def _centric(theta, d, crank, slider, rtol):
    A, C1 = complex(crank.centre_point), complex(slider.moving_pivot)
    beta = float(np.angle(C1 - A)) if C1 != A else float(np.angle(slider.direction))
    rot = np.exp(-1j * beta)
    zB, zC = complex(crank.circle_point), complex(slider.slider_point)
    B, C = (rot * (_images(theta, d, z) - A) for z in (zB, zC))
    a, b = float(crank.length), abs(zC - zB)
    theta_in = np.angle(B)
    size = max(a, b, float(np.max(np.abs(C))))
    best = None
    for branch in (1, -1):
        sol = SliderCrank(a, b, 0.0, branch=branch).solve(theta_in)
        if not np.all(sol.valid):
            continue
        t_rec = np.angle(sol.C - sol.B) + beta - np.angle(zC - zB)
        d_rec = A + np.exp(1j * beta) * sol.B - np.exp(1j * t_rec) * zB
        err = float(max(np.max(np.abs(d_rec - d)) / size, np.max(np.abs(np.angle(np.exp(1j * (t_rec - theta)))))))
        if best is None or err < best[0]:
            best = (err, branch)
    err, branch = best if best is not None else (float("inf"), 1)
    check = guidance_slider_crank(theta, d, crank, slider, rtol=rtol)
    return CentricSliderCrank(SliderCrank(a, b, 0.0, branch=branch), A, beta, crank, slider, theta_in, err,
                              check, bool(check.passes and err <= rtol))


def centric_slider_cranks(theta, d, *, rtol=1e-9, imag_tol=1e-7):
    """Every centric slider-crank through four poses, (2-42), each proved by analysis.

    The guide of the slider pin C passes through the crank's fixed pivot A (Fig. 2-91).
    The pin is the slider point of the four poses (`slider_dyads`); A is a centre point of
    the four poses on its guide, a root of a cubic along the guide; the crank's circle
    point then solves three linear equations. Each linkage is moved by `SliderCrank`
    (offset 0) and by `Linkage` (`guidance_slider_crank`) through the poses.

    Parameters
    ----------
    theta : array_like, shape (4,)
        Pose angles, radians.
    d : array_like of complex, shape (4,)
        Pose translations.
    rtol : float, optional
        Collinearity check of the slider point and the largest accepted pose error.
    imag_tol : float, optional
        A root of the cubic counts as real when its imaginary part is at most this, relative
        to its size (in units of the pose set's size, at least 1).

    Returns
    -------
    tuple of CentricSliderCrank
        Zero to three designs, by crank length; ``passes`` says which reproduce the poses
        in order on one branch.

    Raises
    ------
    ValueError
        For bad poses, or poses whose slider points are not finitely many (`slider_dyads`).

    Notes
    -----
    (2-42) also holds, trivially, with C_1 = A for any centre point; that family of
    spurious roots is avoided by taking C as the slider point. With the centre point
    ``A = C_1 + t e`` on the guide, (2-40) is linear in the circle point with coefficients
    affine in t, and its three equations are consistent where their 3 x 3 determinant, a
    cubic in t, vanishes. The poses are moved to their centroid and scaled first.
    Derivation: :ref:`deriv-displacement`; book page :ref:`synthesis-guidance`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import centric_slider_cranks
    >>> P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j]
    >>> theta = np.radians([0.0, 8.88, 22.1, 63.68])            # example 2-15, poses 1-4
    >>> [(round(k.slider_crank.a, 3), round(k.slider_crank.b, 3), k.passes) for k in centric_slider_cranks(theta, P)]
    [(211.347, 239.286, True)]
    """
    theta, d = pose_set(theta, d, (4,))
    rtol = nonnegative_number("rtol", rtol)
    imag_tol = nonnegative_number("imag_tol", imag_tol)
    found = slider_dyads(theta, d, rtol=rtol)
    if not found:
        return ()
    slider = found[0]
    centre = d.mean()
    size = float(np.max(np.abs(d - centre))) or 1.0
    dn = (d - centre) / size
    A0, e = (slider.line_point - centre) / size, slider.direction
    base = _centric_rows(theta, dn, A0)
    cubic = _det_cubic(np.stack([base, _centric_rows(theta, dn, A0 + e) - base], axis=-1)[None])[0]
    cubic = np.trim_zeros(cubic / np.max(np.abs(cubic)), "b")
    designs = []
    for t in np.roots(cubic[::-1]) if cubic.size > 1 else ():
        if abs(t.imag) > imag_tol * max(1.0, abs(t)):
            continue
        A = A0 + t.real * e
        M = _centric_rows(theta, dn, A)
        xy = np.linalg.lstsq(M[:, :2], -M[:, 2], rcond=None)[0]
        z = complex(xy[0], xy[1]) * size
        Ag = centre + A * size
        B1 = np.exp(1j * theta[0]) * z + d[0]
        length = abs(B1 - Ag)
        if not (length > 0.0 and z != slider.slider_point):
            continue
        designs.append(_centric(theta, d, Dyad(z, complex(B1), complex(Ag), float(length)), slider, rtol))
    designs.sort(key=lambda k: k.crank.length)
    return tuple(designs)
