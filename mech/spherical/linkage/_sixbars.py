"""The Stephenson-1, Stephenson-2, Watt-1 and Watt-2 six-bars on the sphere (monograph §2.4).

Each is the spherical four-bar ABCD (crank AB the input, coupler BC, rocker DC, ground AD
in the default frame of `SphericalFourBar`) with a second dyad E-G-F added; the coupler
point P is carried by the link EG, which never touches the ground. Where E and F sit
decides the type (ternary links in brackets):

========== ==================== ==================== ================================
type       E on                 F on                 ternary links
========== ==================== ==================== ================================
Stephenson-1 the crank (A, B, E)  the rocker (D, C, F)  crank and rocker, not adjacent
Stephenson-2 the coupler (B, C, E) the ground (A, D, F) coupler and ground, not adjacent
Watt-1     the coupler (B, C, E) the rocker (D, C, F)  coupler and rocker, adjacent at C
Watt-2     the rocker (D, C, E)  the ground (A, D, F)  rocker and ground, adjacent at D
========== ==================== ==================== ================================
"""

import numpy as np

from mech._validate import arc as _arc, branch_sign, real_tuple
from mech.spherical._fourbar import _rotation
from mech.spherical.linkage._linkage import SphericalLinkage

__all__ = ["stephenson1", "stephenson2", "watt1", "watt2"]

GROUND = "ground"
_CARRIER = {"stephenson1": ("AB", "DC"), "stephenson2": ("BC", "ground"),
            "watt1": ("BC", "DC"), "watt2": ("DC", "ground")}


def _build(kind, a, b, c, d, E, F, arcs, coupler, branches, frame):
    a, b, c, d = (_arc(n, v) for n, v in zip("abcd", (a, b, c, d)))
    E = real_tuple("E", E, 2)
    F = real_tuple("F", F, 2)
    if not isinstance(arcs, (tuple, list)) or len(arcs) != 2:
        raise ValueError(f"Expected `arcs` to be two arcs (EG, FG), got {arcs!r}")
    e, f = (_arc("arcs", v) for v in arcs)
    coupler = real_tuple("coupler", coupler, 2)
    if not isinstance(branches, (tuple, list)) or len(branches) != 2:
        raise ValueError(f"Expected `branches` to be two signs (+1 or -1), got {branches!r}")
    branches = tuple(branch_sign(v, "branches") for v in branches)
    R = np.eye(3) if frame is None else _rotation(frame)
    A = R[:, 2].copy()
    D = R @ np.array([np.sin(d), 0.0, np.cos(d)])
    lk = (SphericalLinkage({"A": A, "D": D})
          .crank("AB", pivot="A", tip="B", arc=a, reference="D")
          .rrr(("BC", "DC"), pins=("B", "D"), joint="C", arcs=(b, c), branch=branches[0]))
    on_e, on_f = _CARRIER[kind]
    lk = lk.point("E", link=on_e, at=E)
    if on_f == GROUND:
        # eq. (1) in the ground frame, where u = (1, 0, 0) and w = (0, 1, 0) exactly
        r, g = F
        lk = lk.ground("F", R @ np.array([np.sin(r) * np.cos(g), np.sin(r) * np.sin(g), np.cos(r)]))
    else:
        lk = lk.point("F", link=on_f, at=F)
    lk = lk.rrr(("EG", "FG"), pins=("E", "F"), joint="G", arcs=(e, f), branch=branches[1])
    return lk.point("P", link="EG", at=coupler)


_PARAMS = """
    Parameters
    ----------
    a, b, c, d : float
        Arcs of the four-bar ABCD: AB (input crank), BC (coupler), CD (rocker), AD
        (ground), radians in (0, pi); A = (0, 0, 1), D = (sin d, 0, cos d).
    E, F : (float, float)
        The joints E and F as ``(r, gamma)`` in the frames of the links that carry them:
        at arc r from the frame's origin, at angle gamma counter-clockwise (seen from
        outside) from its great circle (crank A->B, coupler B->C, rocker D->C, ground A->D).
    arcs : (float, float)
        Arcs EG and FG of the second dyad.
    coupler : (float, float)
        The coupler point P as ``(r, gamma)`` on the link EG: at arc r from E, at angle
        gamma from the great circle E->G.
    branches : (int, int), optional
        Branches of the dyads B-C-D and E-G-F: +1 puts C left of B->D (G left of E->F)
        seen from outside.
    frame : array_like, shape (3, 3), optional
        Proper rotation placing the linkage anywhere on the sphere (as in
        `SphericalFourBar`; see `ground_frame`): every point is ``frame @`` its position
        in the default frame.

    Returns
    -------
    SphericalLinkage
        Points A, B, C, D, E, F, G, P; links AB, BC, DC, EG, FG (and the ground).
"""


def stephenson1(a, b, c, d, *, E, F, arcs, coupler, branches=(1, 1), frame=None):
    return _build("stephenson1", a, b, c, d, E, F, arcs, coupler, branches, frame)


def stephenson2(a, b, c, d, *, E, F, arcs, coupler, branches=(1, 1), frame=None):
    return _build("stephenson2", a, b, c, d, E, F, arcs, coupler, branches, frame)


def watt1(a, b, c, d, *, E, F, arcs, coupler, branches=(1, 1), frame=None):
    return _build("watt1", a, b, c, d, E, F, arcs, coupler, branches, frame)


def watt2(a, b, c, d, *, E, F, arcs, coupler, branches=(1, 1), frame=None):
    return _build("watt2", a, b, c, d, E, F, arcs, coupler, branches, frame)


stephenson1.__doc__ = """The Stephenson-1 spherical six-bar (monograph §2.4.1).

    The dyad E-G-F joins the crank (ternary: A, B, E) to the rocker (ternary: D, C, F);
    the ground AD is binary, and the two ternary links are not adjacent.
""" + _PARAMS + """
    Examples
    --------
    >>> from mech.spherical import stephenson1
    >>> lk = stephenson1(0.3, 0.9, 0.7, 1.0, E=(0.2, 0.8), F=(0.3, -1.0), arcs=(0.8, 0.7), coupler=(0.4, 0.5))
    >>> lk.points
    ('A', 'D', 'B', 'C', 'E', 'F', 'G', 'P')
"""

stephenson2.__doc__ = """The Stephenson-2 spherical six-bar (monograph §2.4.2).

    The dyad E-G-F joins the coupler (ternary: B, C, E) to a third ground pivot F (the
    ground A, D, F is ternary); the two ternary links are not adjacent. F is given in
    the ground's frame: at arc r from A, at angle gamma from A->D.
""" + _PARAMS + """
    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import stephenson2
    >>> lk = stephenson2(0.3, 0.9, 0.7, 1.0, E=(0.4, 0.7), F=(1.2, 0.5), arcs=(0.7, 0.6), coupler=(0.3, -0.4))
    >>> bool(lk.solve(np.linspace(0, 6.28, 9)).valid.all())
    True
"""

watt1.__doc__ = """The Watt-1 spherical six-bar (monograph §2.4.3).

    The dyad E-G-F joins the coupler (ternary: B, C, E) to the rocker (ternary: D, C, F);
    the ground AD is binary and the ternary links are adjacent (both hold C).
""" + _PARAMS + """
    Examples
    --------
    >>> from mech.spherical import watt1
    >>> lk = watt1(0.3, 0.9, 0.7, 1.0, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4))
    >>> sorted(lk.links)
    ['AB', 'BC', 'DC', 'EG', 'FG', 'ground']
"""

watt2.__doc__ = """The Watt-2 spherical six-bar (monograph §2.4.4): two four-bars in series.

    The dyad E-G-F joins the rocker (ternary: D, C, E) to a third ground pivot F (the
    ground A, D, F is ternary), so the ternary links are adjacent (both hold D); the
    first four-bar ABCD drives the second, DEGF. F is given in the ground's frame: at
    arc r from A, at angle gamma from A->D.
""" + _PARAMS + """
    Examples
    --------
    >>> from mech.spherical import watt2
    >>> lk = watt2(0.3, 0.9, 0.7, 1.0, E=(0.3, 0.5), F=(1.4, 0.4), arcs=(0.6, 0.5), coupler=(0.3, 0.4))
    >>> lk.solve(0.5, order=1).velocities["P"].shape
    (3,)
"""
