"""The transference principle (转换原理): spherical formulas run on dual angles.

One code path serves the spherical four-bar and the spatial RCCC: the generated spherical
coefficients and the atan2 root of :ref:`deriv-one-equation`, evaluated on `Dual` numbers,
give the output angle (real part) and the output slide (dual part). The RSSR follows from
the dual laws of its quadrilateral of lines (:ref:`deriv-spherical-transference`).
"""

import numpy as np

from mech._generated import one_equation as _abc
from mech._generated import transference as _gen
from mech._geometry import cross_components
from mech._scaling import length_scale
from mech._validate import (
    branch_sign, finite_array, finite_result, nonnegative_number, positive_length, real_number,
)
from mech.spherical._dual import Dual

__all__ = ["dual_fourbar_output", "dual_fourbar_joints", "rssr_from_transference"]


def _as_dual(name, value):
    """A dual angle from a `Dual` or a pair ``(angle, distance)`` (or a plain angle)."""
    if isinstance(value, Dual):
        re, du = value.real_part, value.dual_part
    elif isinstance(value, tuple) and len(value) == 2:
        re, du = value
    else:
        re, du = value, 0.0
    return Dual(finite_array(name, re), finite_array(f"{name} (dual part)", du))


def _arc(name, value):
    x = _as_dual(name, value)
    bad = (x.real_part <= 0.0) | (x.real_part >= np.pi)
    if np.any(bad):
        raise ValueError(f"Expected `{name}` with its angle in (0, pi), got {float(x.real_part[bad].ravel()[0])!r}")
    return x


def dual_fourbar_output(a_hat, b_hat, c_hat, d_hat, theta_hat, branch=1):
    """Output dual angle of the spherical four-bar run on dual arcs (the RCCC output).

    The equation A cos(psi) + B sin(psi) = C of the spherical four-bar ((5) of
    :ref:`deriv-one-equation`) and its atan2 root are evaluated on dual numbers: every arc
    becomes a dual twist (twist angle + eps link length), the input a dual joint angle
    (angle + eps offset of the input axis). By the transference principle the result
    psi + eps psi0 is the spatial RCCC's output: real part the spherical output angle, dual
    part psi0 = -S4, minus the slide of the output cylinder.

    Parameters
    ----------
    a_hat, b_hat, c_hat, d_hat : Dual or (array_like, array_like)
        Dual twists of AB, BC, CD, DA: ``(twist, length)``, twists in (0, pi) radians.
    theta_hat : Dual or (array_like, array_like)
        Dual input angle ``(theta, s1)``, theta in the spherical convention.
    branch : {1, -1}, optional
        Assembly branch of the spherical image (``det[B, D, C] > 0`` for +1).

    Returns
    -------
    psi_hat : Dual
        Output dual angle; NaN where the spherical image does not assemble.

    Raises
    ------
    ValueError
        If a twist is outside (0, pi), a value is not finite, or `branch` is not +-1.

    Notes
    -----
    Plain angles (no dual part) give the spherical four-bar itself. The dual part is
    infinite at a limit position of the spherical image. Derivation and checks against the
    H-D closure: :ref:`deriv-spherical-transference`.

    Examples
    --------
    >>> from mech.spherical._transference import dual_fourbar_output
    >>> out = dual_fourbar_output((0.6, 0.2), (1.2, 0.5), (1.0, 0.1), (1.3, 0.4), (0.5, 0.3))
    >>> round(float(out.real_part), 9), round(float(out.dual_part), 9)
    (1.158257792, -0.670423721)
    """
    arcs = [_arc(n, v) for n, v in (("a_hat", a_hat), ("b_hat", b_hat), ("c_hat", c_hat), ("d_hat", d_hat))]
    theta = _as_dual("theta_hat", theta_hat)
    sigma = -branch_sign(branch)
    # NaN where it cannot be assembled (a tiny arc may give 0/0 there): no warning
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        A, B, C = _abc.spherical_fourbar_abc(*arcs, theta)
        disc = _abc.abc_discriminant(A, B, C)
    ok = disc.real_part >= 0.0
    root = np.sqrt(Dual._raw(np.where(ok, disc.real_part, 1.0), np.where(ok, disc.dual_part, 0.0)))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        psi = _abc.abc_solve(A, B, C, root, sigma)
    return Dual._raw(np.where(ok, psi.real_part, np.nan), np.where(ok, psi.dual_part, np.nan))


def _shown(value):
    """A dual argument as the user gave it, for an error message."""
    return value if not isinstance(value, Dual) else (value.real_part, value.dual_part)


def _unit_scale(u):
    """The dual vector `u` divided by the largest magnitude of its real parts (if not zero)."""
    big = np.maximum(np.maximum(np.abs(u[0].real_part), np.abs(u[1].real_part)), np.abs(u[2].real_part))
    _, exp = np.frexp(np.where(big > 0.0, big, 1.0))
    k1, k2 = np.ldexp(1.0, -(exp // 2)), np.ldexp(1.0, exp // 2 - exp)   # powers of two, in two
    return tuple(x * k1 * k2 for x in u)                                   # steps for subnormals


def _dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def dual_fourbar_joints(a_hat, c_hat, d_hat, theta_hat, psi_hat, *, rtol=2.0**-26):
    """Dual angles at the coupler joints B and C of a dual spherical four-bar ((5) there).

    Parameters
    ----------
    a_hat, c_hat, d_hat : Dual or (array_like, array_like)
        Dual twists of AB, CD and DA.
    theta_hat, psi_hat : Dual or (array_like, array_like)
        Dual input and output angles in the spherical convention (a solved pose).
    rtol : float, optional
        Largest estimated rounding error of the dual parts, relative to the largest dual part
        given (default 2**-26, half the digits).

    Returns
    -------
    phi23_hat, phi34_hat : Dual
        The H-D joint dual angles at B and C: angle + eps slide (S2, S3 of the RCCC).

    Notes
    -----
    The dual vectors of the axes B and C come from the generated spherical formulas
    evaluated on dual numbers; the angles are atan2 of dual triple and dot products of the
    common normals (:ref:`deriv-spherical-transference`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._transference import dual_fourbar_joints, dual_fourbar_output
    >>> args = (0.6, 0.2), (1.0, 0.1), (1.3, 0.4), (0.5, 0.3)
    >>> psi = dual_fourbar_output(args[0], (1.2, 0.5), *args[1:])
    >>> phi23, phi34 = dual_fourbar_joints(*args, psi)
    >>> np.round([phi23.real_part, phi23.dual_part, phi34.real_part, phi34.dual_part], 6)
    array([ 0.424231, -0.58498 , -2.266149,  0.135527])
    """
    a, c, d = (_arc(n, v) for n, v in (("a_hat", a_hat), ("c_hat", c_hat), ("d_hat", d_hat)))
    theta, psi = _as_dual("theta_hat", theta_hat), _as_dual("psi_hat", psi_hat)
    rtol = nonnegative_number("rtol", rtol)
    Bx, By, Bz, Cx, Cy, Cz = _gen.spherical_fourbar_vectors(a, c, d, theta, psi)
    zero = Dual(0.0)
    A, B, C = (zero, zero, Dual(1.0)), (Bx, By, Bz), (Cx, Cy, Cz)
    D = (np.sin(d), zero, np.cos(d))
    # each normal scaled by the size of its real part (a positive real factor leaves both
    # parts of the angles unchanged), so tiny arcs neither underflow nor divide by zero
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):   # checked below
        x2, x3, x4 = (_unit_scale(x) for x in (cross_components(A, B), cross_components(B, C), cross_components(C, D)))
        phi23 = np.arctan2(_dot(cross_components(x2, x3), B), _dot(x2, x3))
        phi34 = np.arctan2(_dot(cross_components(x3, x4), C), _dot(x3, x4))
    for value, what in ((phi23, "the dual angle phi23"), (phi34, "the dual angle phi34")):
        finite_result(np.stack(np.broadcast_arrays(value.real_part, value.dual_part)), what,
                      a_hat=_shown(a_hat), c_hat=_shown(c_hat), d_hat=_shown(d_hat))
    # two nearly parallel axes (a twist near 0 or pi): the dual part of their scaled normal
    # holds a component along its real part of about (offset / twist), which the angles
    # cancel in exact arithmetic; in floating point it leaves an error of eps times it
    # (a = 1e-300 gave 3.6e283 where the dual part is -0.333): refuse, naming the givens
    size = max(float(np.max(np.abs(v.dual_part))) for v in (a, c, d, theta, psi))
    for x, axes in ((x2, "A and B"), (x3, "B and C"), (x4, "C and D")):
        with np.errstate(over="ignore", invalid="ignore"):
            err = np.finfo(float).eps * max(float(np.max(np.abs(u.dual_part))) for u in x)
        if not err <= rtol * size:
            raise ValueError(
                f"Expected `a_hat`, `c_hat`, `d_hat`, `theta_hat` and `psi_hat` whose axes {axes} are not so "
                f"nearly parallel that rounding swamps the dual parts (error about {err:.3g} > `rtol` * "
                f"{size:.3g}), got a_hat={_shown(a_hat)}, c_hat={_shown(c_hat)}, d_hat={_shown(d_hat)}, "
                f"theta_hat={_shown(theta_hat)}, psi_hat={_shown(psi_hat)}"
            )
    return phi23, phi34


def rssr_from_transference(l1, l2, l3, s0, s3, h0, lam, phi01, *, branch=1):
    """Output angle of the RSSR of (2-69) to (2-71) by the dual laws of its lines.

    The input axis, crank line, rocker line and output axis form a dual spherical
    quadrilateral; its dual cosine and sine-cosine laws (generated, evaluated on dual
    numbers) give the dual angle of the crank and rocker lines and the feet of their common
    normal, and the coupler condition (6) of :ref:`deriv-spherical-transference` is the
    distance of B and C on those lines. Its coefficients A, B, C of
    A cos(phi03) + B sin(phi03) = C are read off at eight rocker angles (a least-squares
    fit weighted by sin(gamma)**4, exact for this form) and solved by atan2.

    Parameters
    ----------
    l1, l2, l3, s0, s3, h0, lam : float
        Dimensions as in `mech.spatial.RSSR`.
    phi01 : array_like
        Crank angles, radians.
    branch : {1, -1}, optional
        As in `mech.spatial.RSSR` (+1: the + sign of the root in (2-71)).

    Returns
    -------
    phi03 : ndarray
        Rocker angle in (-pi, pi]; NaN where the linkage does not assemble.

    Raises
    ------
    ValueError
        If a length is not positive, a value is not finite, or `branch` is not +-1.

    Notes
    -----
    A second route to `mech.spatial.RSSR`, for checking and teaching, not for speed: the
    discriminant here is the plain A**2 + B**2 - C**2, less accurate near the limit
    positions than the RSSR's factored one.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._transference import rssr_from_transference
    >>> from mech.spatial import RSSR
    >>> dims = (1.0, 4.0, 2.0, 0.5, 0.8, 3.0, np.radians(60))
    >>> phi = np.radians([0, 90, 180])
    >>> bool(np.allclose(rssr_from_transference(*dims, phi), RSSR(*dims).solve(phi).phi03, atol=1e-12))
    True
    """
    l1, l2, l3 = (positive_length(n, v) for n, v in (("l1", l1), ("l2", l2), ("l3", l3)))
    s0, s3, h0, lam = (real_number(n, v) for n, v in (("s0", s0), ("s3", s3), ("h0", h0), ("lam", lam)))
    sigma = branch_sign(branch)
    phi01 = finite_array("phi01", phi01)
    # angles only: in units of a power of two near the longest length, so that no square of
    # a length leaves the float range (lengths of 1e+-300 gave NaN)
    unit = length_scale(l1, l2, l3, s0, s3, h0)
    given = (l1, l2, l3, s0, s3, h0)
    l1, l2, l3, s0, s3, h0 = (x / unit for x in given)
    if l1 * l3 < 2.0**-500:         # the equation is divided by l1 l3, as in `mech.spatial.RSSR`
        raise ValueError(
            f"Expected `l1` * `l3` >= 2**-500 * {max(abs(x) for x in given)!r}**2 (the largest length or "
            f"offset, squared) so that the coefficients stay finite, got `l1` = {given[0]!r}, `l3` = {given[2]!r}"
        )
    samples = (np.arange(8) + 0.5) * (np.pi / 4)
    th = Dual(phi01[..., None], s0)
    ps = Dual(np.broadcast_to(samples, phi01.shape + (8,)), s3)
    cos_gamma, X2, Y2, X4, Y4 = _gen.rssr_dual_laws(th, ps, Dual(-lam, h0))
    theta2, theta4 = np.arctan2(Y2, X2), np.arctan2(Y4, X4)
    sin2 = X2.real_part**2 + Y2.real_part**2
    c = cos_gamma.real_part
    usable = sin2 > 0.0
    safe = np.where(usable, sin2, 1.0)
    u = l1 - np.where(usable, theta2.dual_part, 0.0)
    v = l3 + np.where(usable, theta4.dual_part, 0.0)
    g2 = cos_gamma.dual_part**2 / safe
    F = g2 + u * u + v * v - 2.0 * c * u * v - l2 * l2          # = 2 l1 l3 (A cos + B sin - C)
    weight = np.where(usable, sin2, 0.0)
    rows = np.stack([np.cos(samples), np.sin(samples), -np.ones(8)], axis=-1) * weight[..., None]
    rhs = F / (2.0 * l1 * l3) * weight
    normal = np.einsum("...ki,...kj->...ij", rows, rows)
    coef = np.linalg.solve(normal, np.einsum("...ki,...k->...i", rows, rhs)[..., None])[..., 0]
    A, B, C = coef[..., 0], coef[..., 1], coef[..., 2]
    disc = _abc.abc_discriminant(A, B, C)
    ok = disc >= 0.0
    psi = _abc.abc_solve(A, B, C, np.sqrt(np.where(ok, disc, 0.0)), sigma)
    return np.where(ok, psi, np.nan)[()]
