"""Exact design of Stephenson-1, Stephenson-2 and Watt-1 guidance six-bars for two to five
orientations with prescribed input angles, by kinematic inversion (the spherical monograph,
chapter 4: §4.1.2 for the Stephenson-1; the monograph's table of contents at hand stops there, so the
sections of the other two are not known).

Each type is designed as three guidance dyads in turn. The rotations of one link seen from
another link whose motion is already known are a set of orientations; a guidance dyad of
that set (a circle point on the moving link, a centre point on the reference link) is a
binary link joining the two. Derivation: :ref:`deriv-spherical-guidance-sixbar`, eqs. (7)
to (12).
"""

from dataclasses import dataclass, replace

import numpy as np

from mech._validate import InputTypeError, _show, finite_array
from mech.spherical._rigid_body import angle_at, rotation_matrix
from mech.spherical.guidance._burmester import burmester, circle_point_curve
from mech.spherical.guidance._dyads import SphericalDyad, arc_between, dyad_for_circle_point
from mech.spherical.guidance._fourbar import _rotation_gap
from mech.spherical.guidance._sixbar import _exact_task, _frame
from mech.spherical.linkage._linkage import SphericalLinkage

__all__ = ["SphericalExactSixBar", "guidance_stephenson1", "guidance_stephenson2", "guidance_watt1"]

#: Two joints closer than this (sine of their arc) make no linkage.
_COINCIDENT = 1e-6
#: Which link carries E and F in each design, and the stage joints (circle, centre).
_LAYOUT = {
    "stephenson1": dict(E="DC", F="AB", stages=(("E", "D"), ("B", "C"), ("G", "F"))),
    "stephenson2": dict(E="BC", F="ground", stages=(("E", "B"), ("C", "D"), ("G", "F"))),
    "watt1": dict(E="BC", F="DC", stages=(("E", "B"), ("C", "D"), ("G", "F"))),
}


@dataclass(frozen=True)
class SphericalExactSixBar:
    """One six-bar designed by `guidance_stephenson1`, `guidance_stephenson2` or `guidance_watt1`.

    Attributes
    ----------
    kind : str
        ``"stephenson1"``, ``"stephenson2"`` or ``"watt1"``.
    linkage : SphericalLinkage
        Ground points A, D (and F for the Stephenson-2); crank AB (the input); dyad B-C-D;
        E and F on the links of the type; dyad E-G-F; the guided link is EG.
    input_offset : float
        The linkage's input angle is ``theta_j + input_offset`` at orientation j.
    points : dict of str -> ndarray, shape (3,)
        A, B, C, D, E, F, G at the first orientation (ground frame).
    body : ndarray, shape (3, 3)
        The guided body's axes in the frame of EG: the orientation reached is
        ``F(E, G) @ body`` with F the frame of `sixbar_orientations`.
    stages : tuple of SphericalDyad
        The three dyads in the order they were designed, eqs. (7) to (12).
    errors : ndarray, shape (n,)
        Orientation error (radians) at each prescribed input, by analysis with
        `SphericalLinkage` on the branches of the first orientation (inf if it cannot
        assemble there).
    pose_error : float
        The largest of `errors`.
    branch_defect : bool
        The joints C or G found by the design lie on the other side of their dyad at some
        orientation than at the first: that orientation is on the other branch.
    in_order : bool
        The linkage assembles at every input from the first prescribed angle to the last.
    gamma_at_poses : ndarray, shape (n, 2)
        Transmission angles at C (between CB and CD) and at G (between GE and GF), in
        [0, pi/2], at the prescribed inputs.
    gamma_min : float
        Smallest transmission angle of either dyad over the sweep from the first input to
        the last.
    passes : bool
        ``in_order``, no branch defect, and ``pose_error <= rtol``.
    """

    kind: str
    linkage: SphericalLinkage
    input_offset: float
    points: dict
    body: np.ndarray
    stages: tuple
    errors: np.ndarray
    pose_error: float
    branch_defect: bool
    in_order: bool
    gamma_at_poses: np.ndarray
    gamma_min: float
    passes: bool

    def guided_orientations(self, theta):
        """Orientation R of the guided body (task frame) at task input angles `theta`."""
        theta = finite_array("theta", theta)
        pose = self.linkage.solve(theta + self.input_offset)
        with np.errstate(invalid="ignore"):
            return _frame(pose.points["E"], pose.points["G"]) @ self.body


def _turn_to(centre, p1, pj):
    """Rotations about `centre` carrying p1 to each pj (equal arcs to `centre`), eqs. (8) and (11)."""
    return _frame(np.broadcast_to(centre, pj.shape), pj) @ _frame(centre, p1).T


def _carry(p1, q1, pj, qj):
    """The rotations of a body whose two points move from p1, q1 to pj, qj, eq. (10)."""
    return _frame(pj, qj) @ _frame(p1, q1).T


def _stage_dyads(M, choice, along, n):
    """Guidance dyads of the orientations M (M[0] = I): the Burmester dyads (five); the
    point of the circle-point cubic nearest the circle point `choice` among 720 tracing
    great circles (four); the dyad of the circle point `choice` (three; for two, its centre
    at the angle `along` on the bisecting great circle)."""
    try:
        if n == 5:
            return list(burmester(M).dyads)
        if n == 4:
            curve = circle_point_curve(M, samples=720)
            cos = np.einsum("...i,i->...", np.nan_to_num(curve.moving_pivot), choice)
            gap = np.where(curve.valid, 1.0 - np.abs(cos), np.inf)
            if not np.isfinite(gap.min()):
                return []
            i, k = np.unravel_index(np.argmin(gap), gap.shape)
            d = curve.dyad(i, k)
            # an axis and its antipode are one joint: keep the end on the side of `choice`
            return [d if cos[i, k] > 0 else SphericalDyad(-d.circle_point, -d.moving_pivot, -d.centre_point, d.arc)]
        return [dyad_for_circle_point(M, choice, along=along)]
    except ValueError:
        return []


def _transmission(J, P1, P2):
    """Angle at J between the great circles J -> P1 and J -> P2, folded into [0, pi/2]
    (NaN where the linkage is not assembled)."""
    u, w = np.cross(J, P1), np.cross(J, P2)
    g = np.abs(np.arctan2(np.einsum("...i,...i->...", J, np.cross(u, w)), np.einsum("...i,...i->...", u, w)))
    return np.minimum(g, np.pi - g)


def _sign(a, b, c):
    return np.sign(np.einsum("...i,...i->...", a, np.cross(b, c)))


def _linkage_of(kind, P, branches=None):
    """The six-bar of type `kind` in the assembly of the joints P (A, B, C, D, E, F, G);
    `branches` (two signs) default to the sides the joints C and G are on. Raises
    ValueError if the joints make no linkage (an arc of 0 or pi)."""
    arc = lambda p, q: float(arc_between(P[p], P[q]))  # noqa: E731
    lay = _LAYOUT[kind]
    ground = {"A": P["A"], "D": P["D"]}
    if lay["F"] == "ground":
        ground["F"] = P["F"]
    if branches is None:
        branches = (1 if _sign(P["B"], P["D"], P["C"]) > 0 else -1, 1 if _sign(P["E"], P["F"], P["G"]) > 0 else -1)
    frames = {"AB": ("A", "B"), "BC": ("B", "C"), "DC": ("D", "C")}
    lk = (SphericalLinkage(ground)
          .crank("AB", pivot="A", tip="B", arc=arc("A", "B"), reference="D")
          .rrr(("BC", "DC"), pins=("B", "D"), joint="C", arcs=(arc("B", "C"), arc("D", "C")), branch=branches[0]))
    for name in ("E", "F"):
        link = lay[name]
        if link != "ground":
            o, t = frames[link]
            lk = lk.point(name, link=link, at=(arc(o, name), float(angle_at(P[o], P[t], P[name]))))
    return lk.rrr(("EG", "FG"), pins=("E", "F"), joint="G", arcs=(arc("E", "G"), arc("F", "G")), branch=branches[1])


def _assemble(kind, P, motion, R1, theta, rtol, sweep):
    """Build the six-bar of the joints P, analyse it and report (None if degenerate)."""
    names = list(P)
    for i, p in enumerate(names):
        for q in names[i + 1:]:
            if np.linalg.norm(np.cross(P[p], P[q])) < _COINCIDENT:
                return None
    try:
        lk = _linkage_of(kind, P)
    except ValueError:
        return None
    offset = float(angle_at(P["A"], P["D"], P["B"])) - float(theta[0])
    body = _frame(P["E"], P["G"]).T @ R1
    # the joints where the design puts them at every orientation (eqs. (7)-(12)), for the branch test
    at = {k: np.einsum("nij,j->ni", motion[k], P[k]) for k in "BCEFG"}
    side = (_sign(at["B"], P["D"], at["C"]), _sign(at["E"], at["F"], at["G"]))
    branch_defect = bool(any(np.any(s != s[0]) for s in side))
    pose = lk.solve(theta + offset)
    with np.errstate(invalid="ignore"):
        got = _frame(pose.points["E"], pose.points["G"]) @ body
    task = motion["G"] @ R1
    err = _rotation_gap(got, task)
    err = np.where(np.isfinite(err), err, np.inf)
    sw = lk.solve(np.linspace(theta[0], theta[-1], sweep) + offset)
    in_order = bool(sw.assembled.all())

    def gammas(p):
        with np.errstate(invalid="ignore"):
            return np.stack([_transmission(p["C"], p["B"], p["D"]), _transmission(p["G"], p["E"], p["F"])], -1)
    g_pose = gammas(pose.points)
    g_sweep = gammas(sw.points)
    gamma_min = float(np.nanmin(g_sweep)) if np.any(np.isfinite(g_sweep)) else float("nan")
    pose_error = float(np.max(err))
    return SphericalExactSixBar(kind, lk, offset, dict(P), body, (), err, pose_error, branch_defect, in_order,
                                g_pose, gamma_min, bool(in_order and not branch_defect and pose_error <= rtol))


def _candidates(kind, Rb, K, A, choices, along):
    """Every joint set of the three stages (eqs. (7)-(12)), with each link's rotations."""
    n = Rb.shape[0]
    I = np.broadcast_to(np.eye(3), Rb.shape)
    T = np.swapaxes(K, -1, -2) @ Rb                           # guided link seen from the crank
    out = []
    if kind == "stephenson1":
        thirds = _stage_dyads(T, choices[2], along[2], n)      # (9): G on EG, F on the crank
        for s1 in _stage_dyads(Rb, choices[0], along[0], n):   # (7), the ground as reference: E, D
            E, D = s1.circle_point, s1.centre_point
            Q = _turn_to(D, E, Rb @ E)                        # (8): the rocker DCE
            # (4): B on the crank, C on the rocker
            for s2 in _stage_dyads(np.swapaxes(Q, -1, -2) @ K, choices[1], along[1], n):
                for s3 in thirds:
                    P = dict(A=A, B=s2.circle_point, C=s2.centre_point, D=D, E=E, F=s3.centre_point,
                             G=s3.circle_point)
                    out.append((P, dict(B=K, C=Q, E=Rb, F=K, G=Rb), (s1, s2, s3)))
        return out
    # (12): G, F of the body's orientations (Stephenson-2) does not depend on the other stages
    fixed_third = _stage_dyads(Rb, choices[2], along[2], n) if kind == "stephenson2" else None
    for s1 in _stage_dyads(T, choices[0], along[0], n):       # (9): E on EG, B on the crank
        E, B = s1.circle_point, s1.centre_point
        U = _carry(B, E, K @ B, Rb @ E)                       # (10): the coupler BCE
        for s2 in _stage_dyads(U, choices[1], along[1], n):   # C on the coupler, D on the ground
            C, D = s2.circle_point, s2.centre_point
            if kind == "stephenson2":
                Q, thirds = I, fixed_third                    # F on the ground
            else:
                Q = _turn_to(D, C, U @ C)                     # (11): the rocker DCF
                thirds = _stage_dyads(np.swapaxes(Q, -1, -2) @ Rb, choices[2], along[2], n)   # (12')
            for s3 in thirds:
                P = dict(A=A, B=B, C=C, D=D, E=E, F=s3.centre_point, G=s3.circle_point)
                out.append((P, dict(B=K, C=U, E=Rb, F=Q, G=Rb), (s1, s2, s3)))
    return out


def _design(kind, R, theta, crank_pivot, circle_points, along, rtol, sweep):
    R, n, theta, A, rtol, sweep = _exact_task(R, theta, crank_pivot, rtol, sweep)
    along = finite_array("along", along)
    if along.shape != (3,):
        raise ValueError(f"Expected `along` of three angles (one per stage), got {_show(along)}")
    choices = [None] * 3
    if circle_points is not None:
        z = finite_array("circle_points", circle_points)
        if z.shape != (3, 3) or not np.all(np.linalg.norm(z, axis=-1) > 0):
            raise ValueError(f"Expected `circle_points` of shape (3, 3) with non-zero rows, got {_show(circle_points)}")
        choices = list(z / np.linalg.norm(z, axis=-1, keepdims=True))
    elif n <= 4:
        raise ValueError(f"Expected `circle_points` (three unit vectors) for {n} orientations, got None")
    # the body frame is the ground frame at the first orientation: every joint is given there
    Rb = R @ R[0].T
    K = rotation_matrix(A, theta - theta[0])
    found = []
    for P, motion, stages in _candidates(kind, Rb, K, A, choices, along):
        made = _assemble(kind, P, motion, R[0], theta, rtol, sweep)
        if made is not None:
            found.append(replace(made, stages=stages))
    found.sort(key=lambda s: (not s.passes, s.pose_error))
    return found


_DOC = """
    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations of the guided body, n = 2 to 5.
    theta : array_like, shape (n,)
        Prescribed input angles, strictly increasing, spanning less than a turn.
    crank_pivot : array_like, shape (3,)
        The fixed axis A of the input crank (a free choice of the design).
    circle_points : array_like, shape (3, 3), optional
        Required for n <= 4 (ignored for five): the circle points of the three stages,
        the joints {joints} at the first orientation (ground frame). For n = 4 each is
        replaced by the nearest point of its stage's circle-point cubic
        (`circle_point_curve`, 720 tracing great circles).
    along : array_like, shape (3,), optional
        For n = 2: where each stage's centre point lies on the great circle bisecting the
        two positions of its circle point, as in `dyad_for_circle_point`, radians
        (0 is the mid-point, a half turn of the link; pi/2 the pole, an arc of pi/2).
    rtol : float, optional
        Largest accepted orientation error, radians.
    sweep : int, optional
        Inputs sampled from the first prescribed angle to the last for the order check.

    Returns
    -------
    list of SphericalExactSixBar
        Every design found, the passing ones first, then by orientation error.

    Raises
    ------
    ValueError
        For bad input: wrong shapes, non-rotations, angles not increasing, a missing
        free parameter.

    Notes
    -----
    Each joint set is built on the branches of the first orientation and solved at the
    prescribed inputs by `SphericalLinkage`; a design whose joints change side at some
    orientation (a branch defect) or that cannot run from the first input to the last (an
    order defect) is reported, not dropped. Degenerate sets (two joints on one axis, such
    as the crank's own axis found as a dyad) are dropped. The free choices are the crank
    axis, and for fewer than five orientations `circle_points` (and `along`).
"""


def guidance_stephenson1(R, theta, crank_pivot, *, circle_points=None, along=(1.0, 1.0, 1.0), rtol=1e-9, sweep=721):
    return _design("stephenson1", R, theta, crank_pivot, circle_points, along, rtol, sweep)


def guidance_stephenson2(R, theta, crank_pivot, *, circle_points=None, along=(1.0, 1.0, 1.0), rtol=1e-9, sweep=721):
    return _design("stephenson2", R, theta, crank_pivot, circle_points, along, rtol, sweep)


def guidance_watt1(R, theta, crank_pivot, *, circle_points=None, along=(1.0, 1.0, 1.0), rtol=1e-9, sweep=721):
    return _design("watt1", R, theta, crank_pivot, circle_points, along, rtol, sweep)


guidance_stephenson1.__doc__ = """Stephenson-1 six-bars guiding a body through orientations at prescribed input angles.

    The exact design of the monograph's §4.1.2, derived anew.

    The Stephenson-1 chain with its ternary links the crank (A, B, F) and the rocker
    (D, C, E); the guided link EG is the one of the chain E-G-F next to the rocker (the
    link next to the crank turns about a pin on it, so it meets only two orientations in
    general, eq. (7') of :ref:`deriv-spherical-guidance-sixbar`). Kinematic inversion in
    three stages: E, D a dyad of the orientations; B, C a dyad of the crank's rotations
    seen from the rocker; G, F a dyad of the guided link's rotations seen from the crank,
    eqs. (4), (7) to (9). Every six-bar is built as a `SphericalLinkage` and analysed.
""" + _DOC.format(joints="E, B, G") + """
    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import guidance_stephenson1, rotation_matrix
    >>> theta = np.array([0.0, 0.4, 0.9])
    >>> R = rotation_matrix([0.2, 0.1, 1.0], [0.0, 0.3, 0.5])
    >>> z = [[0.5, 0.3, 0.8], [0.2, 0.4, 0.9], [0.7, -0.1, 0.7]]
    >>> d = guidance_stephenson1(R, theta, [0.0, 0.0, 1.0], circle_points=z)[0]
    >>> d.kind, bool(np.abs(d.guided_orientations(theta) - R).max() < 1e-9)
    ('stephenson1', True)
"""

guidance_stephenson2.__doc__ = """Stephenson-2 six-bars guiding a body through orientations at prescribed input angles.

    The guided link EG is pinned to the coupler (B, C, E) at E and joined to a third
    ground pivot F through FG. Kinematic inversion in three stages: E, B a dyad of the
    guided link's rotations seen from the crank, which then fixes the coupler's rotations;
    C, D a dyad of the coupler's rotations; G, F a dyad of the orientations, eqs. (9) to
    (12) of :ref:`deriv-spherical-guidance-sixbar`. Every six-bar is built as a
    `SphericalLinkage` and analysed.
""" + _DOC.format(joints="E, C, G") + """
    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import guidance_stephenson2, rotation_matrix
    >>> theta = np.array([0.0, 0.4, 0.9])
    >>> R = rotation_matrix([0.2, 0.1, 1.0], [0.0, 0.3, 0.5])
    >>> z = [[0.5, 0.3, 0.8], [0.2, 0.4, 0.9], [0.7, -0.1, 0.7]]
    >>> designs = guidance_stephenson2(R, theta, [0.0, 0.0, 1.0], circle_points=z)
    >>> bool(np.abs(designs[0].guided_orientations(theta) - R).max() < 1e-9)
    True
"""

guidance_watt1.__doc__ = """Watt-1 six-bars guiding a body through orientations at prescribed input angles.

    The guided link EG is pinned to the coupler (B, C, E) at E and joined to the rocker
    (D, C, F) through FG. Kinematic inversion in three stages: E, B a dyad of the guided
    link's rotations seen from the crank (the coupler's rotations follow); C, D a dyad of
    the coupler's rotations (the rocker's follow); G, F a dyad of the guided link's
    rotations seen from the rocker, eqs. (9) to (12') of
    :ref:`deriv-spherical-guidance-sixbar`. Every six-bar is built as a `SphericalLinkage`
    and analysed.
""" + _DOC.format(joints="E, C, G") + """
    Examples
    --------
    Five orientations of a Watt-1's guided link at five input angles, designed again:

    >>> import numpy as np
    >>> from mech.spherical import guidance_watt1, sixbar_orientations, watt1
    >>> lk = watt1(0.3, 0.9, 0.7, 1.0, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4))
    >>> theta = np.array([0.0, 0.3, 0.6, 0.9, 1.2])
    >>> best = [d for d in guidance_watt1(sixbar_orientations(lk, theta), theta, [0.0, 0.0, 1.0]) if d.passes]
    >>> len(best) > 0, max(d.pose_error for d in best) < 1e-9
    (True, True)
"""
