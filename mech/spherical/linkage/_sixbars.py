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

from mech._validate import arc as _arc, branch_sign, proper_rotation, real_tuple
from mech.spherical.linkage._linkage import SphericalLinkage

__all__ = ["stephenson1", "stephenson2", "stephenson3", "watt1", "watt2"]

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
    R = np.eye(3) if frame is None else proper_rotation("frame", frame)
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


def _dyad_joint(P1, P2, c1, c2, sign):
    """The point J with J.P1 = c1, J.P2 = c2 on the side `sign` of P1 -> P2 (NaN if none)."""
    g = np.sum(P1 * P2, axis=-1)
    n = np.cross(P1, P2)
    nn = np.sum(n * n, axis=-1)
    al = (c1 - g * c2) / nn
    be = (c2 - g * c1) / nn
    with np.errstate(invalid="ignore"):
        ga = sign * np.sqrt((1.0 - (al * al + be * be + 2.0 * al * be * g)) / nn)
    return al[..., None] * P1 + be[..., None] * P2 + ga[..., None] * n


def stephenson3(a, b, c, d, *, E, arcs, H, coupler, mu, branch=1, frame=None):
    from mech._errors import AssemblyError
    from mech._generated import spherical_linkage as _g
    from mech._validate import real_number
    from mech.spherical.linkage._stephenson3 import SphericalStephenson3

    a, b, c, d = (_arc(n, v) for n, v in zip("abcd", (a, b, c, d)))
    E = real_tuple("E", E, 2)
    H = real_tuple("H", H, 2)
    coupler = real_tuple("coupler", coupler, 2)
    if not isinstance(arcs, (tuple, list)) or len(arcs) != 2:
        raise ValueError(f"Expected `arcs` to be two arcs (EG, CG), got {arcs!r}")
    e, k = (_arc("arcs", v) for v in arcs)
    mu = real_number("mu", mu)
    branch = branch_sign(branch)
    R = np.eye(3) if frame is None else proper_rotation("frame", frame)
    A = R[:, 2].copy()
    D = R @ np.array([np.sin(d), 0.0, np.cos(d)])
    B = R @ np.array([np.sin(a), 0.0, np.cos(a)])

    def at(O, X, r, g):
        return np.stack(np.broadcast_arrays(*_g.spherical_link_point(*O.T, *X.T, r, g)), axis=-1)

    Ep = at(A[None], B[None], E[0], E[1])[0]
    m = np.linspace(-np.pi, np.pi, 1441)

    def pose(m):
        m = np.atleast_1d(m)
        n = m.size
        C = at(np.tile(B, (n, 1)), np.tile(Ep, (n, 1)), b, m)
        G = _dyad_joint(C, np.tile(Ep, (n, 1)), np.full(n, np.cos(k)), np.full(n, np.cos(e)), branch)
        Hp = at(C, G, H[0], H[1])
        return C, G, Hp

    with np.errstate(invalid="ignore"):
        f = pose(m)[2] @ D - np.cos(c)
        found = []
        for i in np.flatnonzero(np.isfinite(f[:-1]) & np.isfinite(f[1:]) & (np.sign(f[:-1]) != np.sign(f[1:]))):
            lo, hi, flo = m[i], m[i + 1], f[i]
            for _ in range(100):
                mid = 0.5 * (lo + hi)
                fm = float(pose(mid)[2][0] @ D - np.cos(c))
                if np.sign(fm) == np.sign(flo):
                    lo, flo = mid, fm
                else:
                    hi = mid
            found.append(0.5 * (lo + hi))
    given = (f"`a`={a!r}, `b`={b!r}, `c`={c!r}, `d`={d!r}, `E`={E!r}, `arcs`={arcs!r}, `H`={H!r}, "
             f"`branch`={branch}")
    if not found:
        raise AssemblyError(f"Cannot assemble the Stephenson-3 at theta = 0 with {given}")
    gap = [abs(np.angle(np.exp(1j * (x - mu)))) for x in found]
    m0 = found[int(np.argmin(gap))]
    C, G, Hp = (v[0] for v in pose(m0))
    P = at(C[None], G[None], coupler[0], coupler[1])[0]
    try:
        return SphericalStephenson3({"A": A, "D": D, "B": B, "E": Ep, "C": C, "G": G, "H": Hp}, coupler=P)
    except ValueError as exc:
        raise AssemblyError(f"Cannot assemble the Stephenson-3 at theta = 0 with {given}: {exc}") from None


stephenson3.__doc__ = """The Stephenson-3 spherical six-bar (monograph chapter 4): a binary link of
    the Stephenson chain's two-link path is the ground.

    The crank ABE (ternary) turns about A; the guided link CGH (ternary) hangs from it by
    the binary links BC and EG and from the ground by the binary link DH. The links after
    the crank form a triad, solved by `SphericalStephenson3` (no dyad comes first).

    Parameters
    ----------
    a, b, c, d : float
        Arcs AB (crank), BC, DH and AD (ground), radians in (0, pi); A = (0, 0, 1),
        D = (sin d, 0, cos d).
    E : (float, float)
        E on the crank as ``(r, gamma)``: at arc r from A, at angle gamma counter-clockwise
        (seen from outside) from the great circle A -> B.
    arcs : (float, float)
        Arcs EG and CG.
    H, coupler : (float, float)
        H and the coupler point P on the guided link as ``(r, gamma)``: at arc r from C, at
        angle gamma from the great circle C -> G.
    mu : float
        Picks the assembly at theta = 0: the one whose angle at B, from the great circle
        B -> E to B -> C, is nearest to `mu`.
    branch : int, optional
        +1 puts G to the left of the great circle C -> E seen from outside (the four-bar
        B-C-G-E carried by the crank), -1 to the right.
    frame : array_like, shape (3, 3), optional
        Proper rotation placing the linkage (see `stephenson1`).

    Returns
    -------
    SphericalStephenson3
        Assembled at theta = 0 (the angle at A from A -> D to A -> B).

    Raises
    ------
    ValueError
        If an arc is outside (0, pi).
    AssemblyError
        If the linkage cannot assemble at theta = 0 on `branch` (a `ValueError`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import stephenson3
    >>> lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
    ...                  coupler=(0.3, 0.4), mu=0.8)
    >>> round(lk.arcs["DH"], 12), lk.points
    (0.8, ('A', 'D', 'B', 'E', 'C', 'G', 'H', 'P'))
"""
