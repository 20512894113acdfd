"""Fixed and moving centrodes of the four-bar coupler (instant centre P24, example 2-4)."""

import math
from dataclasses import dataclass

import numpy as np

from mech._generated import instant_centres as _gen
from mech._validate import finite_array, instance, integer, positive_length
from mech.planar.kinematics._fourbar import FourBar

__all__ = ["CentrodeSegment", "CouplerCentrodes", "coupler_centrodes"]

# |W| below this fraction of |(X, Y)| (in units of the linkage size) counts as at infinity.
_INFINITE_RTOL = 1e-12


@dataclass(frozen=True)
class CentrodeSegment:
    """One connected piece of the centrodes between two passages through infinity."""

    theta: np.ndarray
    fixed: np.ndarray
    moving: np.ndarray


@dataclass(frozen=True)
class CouplerCentrodes:
    """The coupler's instant centre P24 over an array of crank angles.

    Attributes
    ----------
    theta : ndarray
        Crank angles, radians.
    fixed : ndarray of complex
        P24 in the frame (the fixed centrode); NaN where at infinity or not assembled.
    moving : ndarray of complex
        P24 in the coupler frame, origin B and x along B->C (the moving centrode).
    homogeneous : ndarray, shape (..., 3)
        ``(X, Y, W)`` of P24 in the frame; ``W = 0`` when AB is parallel to DC.
    at_infinity, valid : ndarray of bool
        Where P24 is at infinity (the coupler translates); where the linkage assembles.
    B, phi : ndarray
        Crank pin and coupler angle at each input angle.
    """

    theta: np.ndarray
    fixed: np.ndarray
    moving: np.ndarray
    homogeneous: np.ndarray
    at_infinity: np.ndarray
    valid: np.ndarray
    B: np.ndarray
    phi: np.ndarray

    def moving_placed(self, index):
        """The moving centrode carried with the coupler to the pose ``theta[index]``.

        Returns ``B + moving * exp(i phi)`` at that pose: it touches the fixed centrode
        at that pose's P24.
        """
        index = integer("index", index, minimum=-self.phi.size, maximum=self.phi.size - 1)
        return self.B[index] + self.moving * np.exp(1j * self.phi[index])

    def segments(self, limit):
        """Split the sampled centrodes into pieces that stay within `limit` of A.

        A piece ends where P24 leaves the disc of radius `limit` about A (in either
        centrode: the moving one is measured from B), goes to infinity, changes sign of
        ``W`` between two samples (it passed through infinity), or cannot be assembled.

        Parameters
        ----------
        limit : float
            Radius of the disc kept, in the linkage's length unit.

        Returns
        -------
        list of CentrodeSegment
            Pieces with at least two samples, in the order of `theta`.
        """
        limit = positive_length("limit", limit)
        theta, fixed, moving = (np.ravel(v) for v in (self.theta, self.fixed, self.moving))
        W = np.ravel(self.homogeneous[..., 2])
        with np.errstate(invalid="ignore"):
            keep = np.ravel(self.valid & ~self.at_infinity) & (np.abs(fixed) <= limit) & (np.abs(moving) <= limit)
        breaks = np.ones(theta.size, dtype=bool)
        breaks[1:] = ~keep[:-1] | (np.sign(W[1:]) != np.sign(W[:-1]))
        pieces = []
        for idx in np.split(np.arange(theta.size), np.flatnonzero(breaks)[1:]):
            idx = idx[keep[idx]]
            if idx.size >= 2:
                pieces.append(CentrodeSegment(theta[idx], fixed[idx], moving[idx]))
        return pieces


def coupler_centrodes(fourbar, theta):
    """Fixed and moving centrodes of the coupler of a four-bar (瞬心线).

    The coupler's absolute instant centre is ``P24 = AB x DC``, where the crank line and
    the rocker line meet (three-centre theorem, F33; example 2-4). Its path in the frame
    is the fixed centrode, its path in the coupler's frame the moving centrode; the
    moving centrode rolls on the fixed one without slipping as the linkage moves.

    Parameters
    ----------
    fourbar : FourBar
        The linkage (its branch is used).
    theta : array_like
        Crank angles, radians.

    Returns
    -------
    CouplerCentrodes
        ``fixed``, ``moving`` (complex; NaN at infinity or where it cannot be assembled),
        ``homogeneous``, ``at_infinity``, ``valid``; ``segments(limit)`` splits the curves
        where they pass through infinity (the crank parallel to the rocker).

    Raises
    ------
    ValueError
        If `theta` is not finite.

    Notes
    -----
    Closed form and checks on the derivation page :ref:`deriv-instant-centres`.

    Examples
    --------
    >>> from mech.planar import FourBar
    >>> from mech.planar.coupler._centrodes import coupler_centrodes
    >>> cen = coupler_centrodes(FourBar(10, 40, 30, 35), [0.7, 2.0])
    >>> cen.valid.tolist(), cen.at_infinity.tolist()
    ([True, True], [False, False])
    >>> bool(abs(abs(cen.moving[0]) - abs(cen.fixed[0] - cen.B[0])) < 1e-9)
    True
    """
    instance("fourbar", fourbar, FourBar)
    theta = finite_array("theta", theta)
    pose = fourbar.solve(theta)
    B, C = pose.B, pose.C
    # the pole's homogeneous coordinates are cubic in the lengths: work on lengths scaled
    # by the power of two that FourBar uses, so that nothing overflows or underflows
    e = fourbar._exponent
    Bs, Cs = np.ldexp(B.real, -e) + 1j * np.ldexp(B.imag, -e), np.ldexp(C.real, -e) + 1j * np.ldexp(C.imag, -e)
    ds, bs = math.ldexp(fourbar.d, -e), math.ldexp(fourbar.b, -e)
    with np.errstate(invalid="ignore"):
        X, Y, W, U, V = _gen.fourbar_coupler_pole(Bs.real, Bs.imag, Cs.real, Cs.imag, ds, bs)
        xy, uv = X + 1j * Y, U + 1j * V
        at_inf = pose.valid & (np.abs(W) <= _INFINITE_RTOL * np.abs(xy) / ds)
        finite = pose.valid & ~at_inf
        safe = np.where(finite, W, 1.0)
        fixed = np.where(finite, xy / safe, np.nan + 0j)
        moving = np.where(finite, uv / safe, np.nan + 0j)
    fixed, moving = (np.ldexp(z.real, e) + 1j * np.ldexp(z.imag, e) for z in (fixed, moving))
    homogeneous = np.stack([np.ldexp(X, e), np.ldexp(Y, e), W], axis=-1)
    return CouplerCentrodes(theta, fixed[()], moving[()], homogeneous, at_inf[()],
                            np.asarray(pose.valid)[()], B, np.asarray(pose.phi)[()])
