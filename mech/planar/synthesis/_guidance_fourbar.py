"""Four-bars from pairs of guidance dyads, each proved by analysis with `FourBar`."""

from dataclasses import dataclass

import numpy as np

from mech._validate import InputTypeError, _show, finite_array, planar_points, real_number
from mech.planar.kinematics._fourbar import FourBar
from mech.planar.structure._grashof import grashof
from mech.planar.synthesis._displacement import pose_set
from mech.planar.synthesis._guidance import Dyad, burmester

__all__ = ["GuidanceFourBar", "GuidanceSynthesis", "guidance_fourbars"]

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


def _wrap(angle):
    return np.angle(np.exp(1j * angle))


def _motion(linkage, theta_in):
    """Direction (+1, -1 or 0) in which the input meets the poses in order, and its path ends.

    The linkage can be assembled on an input interval exactly when it can at the interval's
    ends and at the angles 0 and pi inside it (the diagonal BD is extreme there), so those
    angles decide, by the analysis class itself.
    """
    for direction in (1, -1):
        steps = np.remainder(direction * np.diff(theta_in), _TWO_PI)
        travel = float(np.sum(steps))
        if travel >= _TWO_PI:
            continue
        start = float(theta_in[0])
        lo, hi = (start, start + travel) if direction > 0 else (start - travel, start)
        inside = np.arange(np.ceil(lo / np.pi), np.floor(hi / np.pi) + 1) * np.pi
        critical = np.concatenate([[lo, hi], inside])
        if np.all(linkage.solve(critical).valid):
            return direction, critical
    return 0, None


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
    rtol = real_number("rtol", rtol)
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
