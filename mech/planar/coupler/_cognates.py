"""The Roberts-Chebyshev cognates: three four-bars that trace one coupler curve (Fig. 2-32)."""

import math
from dataclasses import dataclass

import numpy as np

from mech._errors import AssemblyError
from mech._generated import cognates as _gen
from mech._validate import bool_flag, branch_sign, finite_array, instance, planar_points, positive_length
from mech.planar.kinematics._fourbar import FourBar
from mech._pose import Pose

__all__ = ["Cognate", "CognatePose", "Cognates", "TenBarPose", "cognates"]

#: Which link of each linkage turns with the original crank AB (see the derivation page).
_DRIVER = {"ABCD": "crank", "AEGK": "coupler", "DFHK": "rocker"}


class CognatePose(Pose):
    """A cognate solved at its own crank angles, placed in the original frame.

    Attributes
    ----------
    theta : ndarray
        The cognate's own crank angles (in its standard frame), radians.
    B, C, P : ndarray of complex
        Its crank pin, rocker pin and coupler point in the ORIGINAL frame (for AEGK these
        are the textbook's E, G, M; for DFHK they are F, H, M).
    valid : ndarray of bool
        False where the cognate cannot be assembled (NaN there).
    """


@dataclass(frozen=True)
class TenBarPose:
    """The joints of the Roberts-Chebyshev ten-bar (Fig. 2-32) at original crank angles.

    Every attribute is a complex array shaped like the input angles, in the original frame;
    ``A``, ``D`` and ``K`` are the fixed pivots. ``M`` has a leading axis of 3: the coupler
    point as computed through ABCD, AEGK and DFHK (equal up to rounding).
    """

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    E: np.ndarray
    F: np.ndarray
    G: np.ndarray
    H: np.ndarray
    K: np.ndarray
    M: np.ndarray
    valid: np.ndarray


class Cognate:
    """One of the three four-bars tracing a coupler curve, placed in the original frame.

    Built by `cognates`; not meant to be constructed directly.

    Attributes
    ----------
    name : {"ABCD", "AEGK", "DFHK"}
        The textbook's letters: crank pivot, crank pin, rocker pin, rocker pivot.
    fourbar : FourBar
        The linkage in its own standard frame (crank pivot at 0, rocker pivot at +d), with
        its coupler point and the branch it has at the first assembled pose of the original.
    origin, rotation : complex
        The placement ``z -> origin + rotation * z`` from its frame to the original's.
    driver : {"crank", "coupler", "rocker"}
        Its link that turns with the original crank AB.
    """

    def __init__(self, name, fourbar, origin, rotation):
        self.__dict__.update(name=name, fourbar=fourbar, origin=complex(origin),
                             rotation=complex(rotation), driver=_DRIVER[name])

    def __setattr__(self, name, value):
        raise AttributeError("Cognate is immutable")

    @property
    def lengths(self):
        """Crank, coupler, rocker and ground lengths ``(a, b, c, d)``."""
        f = self.fourbar
        return (f.a, f.b, f.c, f.d)

    @property
    def coupler(self):
        """Coupler-point offset ``(p, q)`` in the `FourBar` convention."""
        return self.fourbar.coupler

    @property
    def pivots(self):
        """Crank pivot and rocker pivot in the original frame, complex."""
        return self.origin, self._place(self.fourbar.d)

    def place(self, z):
        """Map points of the cognate's own frame to the original frame."""
        return self._place(planar_points("z", z))

    def _place(self, z):
        # unchecked: the poses solved below carry NaN where they cannot be assembled
        return self.origin + self.rotation * np.asarray(z)

    def solve(self, theta, *, branch=None, strict=False):
        """Solve the cognate at its own crank angles and place it in the original frame.

        Parameters
        ----------
        theta : array_like
            The cognate's crank angle in its own frame, radians. For AEGK and DFHK this is
            the original coupler angle: ``solve(original_pose.phi)`` gives the same pose.
        branch : {1, -1}, optional
            The cognate's own assembly branch; default ``self.fourbar.branch``.
        strict : bool, optional
            Raise `AssemblyError` where it cannot be assembled.

        Returns
        -------
        CognatePose
            ``B, C, P`` in the original frame, ``valid`` and ``theta``.

        Examples
        --------
        >>> from mech.planar import FourBar
        >>> from mech.planar.coupler._cognates import cognates
        >>> trio = cognates(FourBar(1, 2, 2.5, 3, coupler=(1, 1)))
        >>> pose = trio.aegk.solve([0.5, 1.0], branch=1)
        >>> pose.P.shape
        (2,)
        """
        strict = bool_flag("strict", strict)
        fb = self.fourbar
        if branch is not None and branch_sign(branch) != fb.branch:
            fb = FourBar(fb.a, fb.b, fb.c, fb.d, branch=branch, coupler=fb.coupler)
        own = fb.solve(theta, strict=False)
        if strict and not np.all(own.valid):
            bad = float(np.broadcast_to(own.theta, own.valid.shape)[~own.valid][0])
            raise AssemblyError(f"Cannot assemble cognate {self.name} at theta = {bad!r}")
        fields = {"B": self._place(own.B)[()], "C": self._place(own.C)[()],
                  "P": self._place(own.P)[()], "valid": own.valid, "theta": own.theta}
        return CognatePose(0, fields)

    def __repr__(self):
        return (f"Cognate({self.name!r}, {self.fourbar!r}, origin={self.origin!r}, "
                f"rotation={self.rotation!r})")


class Cognates:
    """The three four-bars ABCD, AEGK and DFHK of Fig. 2-32 that trace one coupler curve.

    Returned by `cognates`. Iterating gives the three `Cognate` objects in that order.

    Attributes
    ----------
    abcd, aegk, dfhk : Cognate
        The original and its two cognates.
    K : complex
        The third fixed pivot, ``K = lam * d``.
    ratio : complex
        ``lam = (p + 1j*q) / b``: triangle ADK is triangle BCM scaled and turned by it.
    """

    def __init__(self, original):
        instance("original", original, FourBar)
        a, b, c, d = original.a, original.b, original.c, original.d
        p, q = original.coupler
        beta = original.branch
        positive_length("|MB|", np.hypot(p, q))
        positive_length("|MC|", np.hypot(b - p, q))
        # the generated formulas multiply lengths: feed them the lengths scaled by the
        # power of two FourBar uses, and scale the resulting lengths back (exactly)
        e = original._exponent
        (Kx, Ky, a1, b1, c1, d1, p1, q1, cos1, sin1,
         a2, b2, c2, d2, p2, q2, cos2, sin2) = (float(x) for x in _gen.cognate_dimensions(
            *(math.ldexp(v, -e) for v in (a, b, c, d, p, q))))
        Kx, Ky, a1, b1, c1, d1, p1, q1, a2, b2, c2, d2, p2, q2 = (
            math.ldexp(v, e) for v in (Kx, Ky, a1, b1, c1, d1, p1, q1, a2, b2, c2, d2, p2, q2))
        # Drivers: each cognate solved through the link that turns with AB (derivation page).
        # AEGK driven by its coupler: the loop with crank and coupler swapped, same branch.
        # DFHK driven by its rocker: the linkage turned by pi about the midpoint of DK.
        drivers = (original, FourBar(b1, a1, c1, d1, branch=beta), FourBar(c2, b2, a2, d2, branch=-beta))
        self.__dict__.update(K=complex(Kx, Ky), ratio=complex(p, q) / b, _drivers=drivers,
                             _own=((a1, b1, c1, d1, p1, q1), (a2, b2, c2, d2, p2, q2)),
                             _rotations=(complex(cos1, sin1), complex(cos2, sin2)))
        own_branches = self._reference_branches()
        linkages = (
            Cognate("ABCD", original, 0.0, 1.0),
            Cognate("AEGK", FourBar(a1, b1, c1, d1, branch=own_branches[1], coupler=(p1, q1)),
                    0.0, self._rotations[0]),
            Cognate("DFHK", FourBar(a2, b2, c2, d2, branch=own_branches[2], coupler=(p2, q2)),
                    d, self._rotations[1]),
        )
        self.__dict__.update(linkages=linkages, abcd=linkages[0], aegk=linkages[1], dfhk=linkages[2])

    def __setattr__(self, name, value):
        raise AttributeError("Cognates is immutable")

    def __iter__(self):
        return iter(self.linkages)

    def __repr__(self):
        return f"Cognates({self.abcd.fourbar!r}, K={self.K!r})"

    def _reference_branches(self):
        """Own branches of the three at the first assembled pose of the original (1 if none)."""
        theta = np.linspace(0.0, 2 * np.pi, 361)[:-1]
        signs = self.branches(theta)
        ok = np.all(signs != 0, axis=0)
        if not np.any(ok):
            return (self._drivers[0].branch, 1, 1)
        return tuple(int(s) for s in signs[:, np.argmax(ok)])

    def joints(self, theta):
        """All joints of the ten-bar at the original crank angles `theta`.

        Each cognate is solved through its own dimensions, driven by the link that turns
        with the original crank; the result is placed in the original frame.

        Returns
        -------
        TenBarPose
            ``A, B, C, D, E, F, G, H, K, M`` (complex) and ``valid``.
        """
        theta = finite_array("theta", theta)
        d = self._drivers[0].d
        (a1, b1, c1, d1, p1, q1), (a2, b2, c2, d2, p2, q2) = self._own
        rot1, rot2 = self._rotations
        orig = self._drivers[0].solve(theta)
        # AEGK: crank b1 along its coupler EG at angle theta; C' = G, C' - B' = E (own frame)
        s1 = self._drivers[1].solve(theta)
        E1 = s1.C - s1.B
        G1 = s1.C
        M1 = E1 + complex(p1, q1) * (s1.B / b1)
        # DFHK: B' = d2 - H, C' = d2 - F (own frame), coupler direction (C' - B') / b2
        s2 = self._drivers[2].solve(theta)
        H2, F2 = d2 - s2.B, d2 - s2.C
        M2 = F2 + complex(p2, q2) * ((s2.C - s2.B) / b2)
        valid = orig.valid & s1.valid & s2.valid
        z = np.zeros_like(orig.B)
        return TenBarPose(
            A=z[()], B=orig.B, C=orig.C, D=(z + d)[()],
            E=(rot1 * E1)[()], F=(d + rot2 * F2)[()], G=(rot1 * G1)[()], H=(d + rot2 * H2)[()],
            K=(z + self.K)[()], M=np.stack([orig.P, rot1 * M1, d + rot2 * M2]),
            valid=valid,
        )

    def path(self, theta):
        """Coupler points of ABCD, AEGK and DFHK at the original crank angles `theta`.

        Returns a complex array of shape ``(3,) + theta.shape`` in the original frame:
        the three coincide (the Roberts-Chebyshev theorem), each computed through its own
        link lengths and coupler offset. NaN where the original cannot be assembled.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.planar import FourBar
        >>> from mech.planar.coupler._cognates import cognates
        >>> M = cognates(FourBar(1, 2, 2.5, 3, coupler=(1, 1))).path(np.linspace(0, 6, 4))
        >>> M.shape, bool(np.ptp(M, axis=0).max() < 1e-12)
        ((3, 4), True)
        """
        return self.joints(theta).M

    def branches(self, theta):
        """Own assembly branches (+1, -1) of ABCD, AEGK and DFHK at original crank angles.

        A cognate keeps one branch along a circuit only if its crank revolves; otherwise
        the sign flips at its limit positions. 0 where the original cannot be assembled.
        Shape ``(3,) + theta.shape``.
        """
        j = self.joints(theta)
        e = self._drivers[0]._exponent

        def unit(z):
            # the product of two lengths could overflow; only its sign is wanted
            return np.ldexp(z.real, -e) + 1j * np.ldexp(z.imag, -e)

        def sign(pivot, pin, far):
            s = np.sign((unit(pivot - pin).conjugate() * unit(far - pin)).imag)
            return np.where(j.valid, s, 0).astype(int)

        return np.stack([sign(j.D, j.B, j.C), sign(j.K, j.E, j.G), sign(j.K, j.F, j.H)])[()]


def cognates(fourbar):
    """The Roberts-Chebyshev cognates of a four-bar with a coupler point (Fig. 2-32).

    Completing the parallelograms ABME and DCMF, the triangles GEM and HMF similar to
    MBC, and the parallelogram GMHK gives a fixed pivot K = lam * d with
    lam = (p + 1j*q) / b (triangle ADK similar to BCM) and two more four-bars, AEGK and
    DFHK, whose coupler point is M: all three trace the same coupler curve.

    Parameters
    ----------
    fourbar : FourBar
        The original linkage ABCD with its coupler point M ``coupler=(p, q)`` and branch.

    Returns
    -------
    Cognates
        ``abcd``, ``aegk``, ``dfhk`` (each a `Cognate`: own-frame `FourBar`, placement,
        lengths, coupler offset), the pivot ``K``, and ``path(theta)`` giving the three
        coupler points at the original crank angles in one call.

    Raises
    ------
    TypeError
        If `fourbar` is not a `FourBar`.
    ValueError
        If the coupler point is at B or at C (a cognate would shrink to a point).

    Notes
    -----
    AEGK has the lengths ``|lam| (b, a, c, d)``: its crank AE turns with the original
    coupler BC, its coupler EG with the original crank AB, its rocker with the original
    rocker. DFHK has ``|lam - 1| (b, c, a, d)``: crank DF with BC, coupler FH with DC,
    rocker KH with AB. In its own frame each cognate's crank angle equals the original
    coupler angle phi. A cognate keeps one assembly branch along a circuit only when its
    crank revolves (the original is a double-crank, or a double-rocker with the coupler
    shortest); otherwise its branch flips at its own limit positions, and
    `Cognates.branches` says which applies where (the two cognates' own branches are
    always opposite). Derivation page :ref:`deriv-cognates`.

    Examples
    --------
    >>> from mech.planar import FourBar
    >>> from mech.planar.coupler._cognates import cognates
    >>> trio = cognates(FourBar(1, 2, 2.5, 3, coupler=(1, 1)))
    >>> trio.K
    (1.5+1.5j)
    >>> [round(x, 6) for x in trio.aegk.lengths]
    [1.414214, 0.707107, 1.767767, 2.12132]
    >>> [c.driver for c in trio]
    ['crank', 'coupler', 'rocker']
    """
    if not isinstance(fourbar, FourBar):
        raise TypeError(f"Expected `fourbar` to be a FourBar, got {fourbar!r}")
    return Cognates(fourbar)
