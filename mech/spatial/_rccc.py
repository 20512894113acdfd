"""The spatial RCCC four-bar: the spherical four-bar with dual angles (transference)."""

import numpy as np

from mech._errors import AssemblyError
from mech._generated import one_equation as _abc
from mech._generated import transference as _gen
from mech._pose import mask_singular_rates, Pose
from mech._validate import bool_flag, branch_sign, common_shape, finite_array, nonnegative_int, real_number

__all__ = ["RCCC", "RCCCPose"]


class RCCCPose(Pose):
    """Poses of an RCCC at an array of input angles (returned by `RCCC.solve`).

    Attributes
    ----------
    theta, valid : ndarray
        Input angle phi12 and the mask of assembled poses.
    phi41, s4 : ndarray
        Output angle phi41 in (-pi, pi] and output slide S4 of the cylinder at D (H-D).
    phi23, s2, phi34, s3 : ndarray
        Angles and slides of the middle cylinders at B and C (H-D).
    omega_output, v_output : ndarray
        d phi41/dt and d S4/dt; present when solved with ``order >= 1``.
    assembled : ndarray of bool
        True where the position exists. With ``order >= 1``, ``valid`` is False also where
        a solved rate is infinite or undetermined (a dead point; those rates are NaN
        there), while ``assembled`` stays True (the rule of `mech._pose.Pose`).
    """

    _ORDER_OF = {"omega_output": 1, "v_output": 1}


class RCCC:
    """The RCCC spatial four-bar: input revolute at A, cylindric pairs at B, C and D.

    H-D frames as in (2-67) and :ref:`deriv-transforms` (``mech.spatial.hd``): z1..z4 on the
    joint axes at A, B, C, D, x_j on the common normal from z_i to z_j, and the loop closes
    as ``hd(phi12, a, s1, a0) @ hd(phi23, b, s2, b0) @ hd(phi34, c, s3, c0) @
    hd(phi41, d, s4, d0) = I``.

    Parameters
    ----------
    a, b, c, d : (float, float)
        Dual twists ``(twist, length)`` of the links AB, BC, CD and DA (ground): H-D
        (lambda12, h2), (lambda23, h3), (lambda34, h4), (lambda41, h1). Twists in (0, pi)
        radians, lengths any real (signed along x_j).
    s1 : float, optional
        Offset S1 of the input revolute (fixed).
    branch : {1, -1}, optional
        Assembly mode: the branch of the spherical image (the axes moved through one
        point), +1 when det[z2, z4, z3] > 0 (CONVENTIONS.md, spherical four-bar).

    Raises
    ------
    ValueError
        If a twist is outside (0, pi), a value is not finite or `branch` is not +-1.

    Notes
    -----
    The transference principle (:ref:`deriv-spherical-transference`): the output angle is
    the spherical four-bar's with the twists as arcs, theta = phi12 - pi and
    psi = -phi41; the output slide is the dual part (4) there, S4 = -psi0. At a limit
    position of the spherical image the slide and the rates are unbounded. With all twists
    zero (parallel axes, a planar loop) the principle gives nothing, and twists must be in
    (0, pi).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._rccc import RCCC
    >>> rccc = RCCC((0.6, 0.2), (1.2, 0.5), (1.0, 0.1), (1.3, 0.4), s1=0.3)
    >>> pose = rccc.solve(0.5 + np.pi)
    >>> round(float(pose.phi41), 9), round(float(pose.s4), 9)
    (-1.158257792, 0.670423721)
    >>> rccc.solve(np.linspace(0, 2 * np.pi, 5), order=1).v_output.shape
    (5,)
    """

    def __init__(self, a, b, c, d, *, s1=0.0, branch=1):
        twists, lengths = [], []
        for name, pair in (("a", a), ("b", b), ("c", c), ("d", d)):
            try:
                twist, length = pair
            except (TypeError, ValueError):
                raise ValueError(f"Expected `{name}` to be a pair (twist, length), got {pair!r}") from None
            twist = real_number(name, twist)
            if not 0.0 < twist < np.pi:
                raise ValueError(f"Expected the twist of `{name}` in (0, pi), got {twist!r}")
            twists.append(twist)
            lengths.append(real_number(f"{name} length", length))
        self._twists, self._lengths = tuple(twists), tuple(lengths)
        self._s1 = real_number("s1", s1)
        self._branch = branch_sign(branch)

    twists = property(lambda self: self._twists, doc="Twists (lambda12, lambda23, lambda34, lambda41).")
    lengths = property(lambda self: self._lengths, doc="Lengths (h2, h3, h4, h1).")
    s1 = property(lambda self: self._s1, doc="Offset S1 of the input revolute.")
    branch = property(lambda self: self._branch, doc="Assembly mode, +1 or -1.")

    def __repr__(self):
        pairs = ", ".join(repr(p) for p in zip(self._twists, self._lengths))
        return f"RCCC({pairs}, s1={self._s1!r}, branch={self._branch})"

    def solve(self, theta, order=0, omega=1.0, strict=False):
        """Output angle and slide (and the middle cylinders) at input angles `theta`.

        Parameters
        ----------
        theta : array_like
            Input angle phi12 (H-D, about z1 from x1 to x2), radians.
        order : {0, 1}, optional
            1 adds the rates ``omega_output`` (d phi41/dt) and ``v_output`` (d S4/dt).
        omega : array_like, optional
            d phi12/dt.
        strict : bool, optional
            Raise `AssemblyError` at the first input that cannot be assembled, instead of
            returning NaN there.

        Returns
        -------
        RCCCPose

        Raises
        ------
        AssemblyError
            With ``strict=True``, naming the first input angle that cannot be assembled.

        Examples
        --------
        >>> from mech.spatial._rccc import RCCC
        >>> pose = RCCC((0.6, 0.2), (1.2, 0.5), (1.0, 0.1), (1.3, 0.4)).solve([0.0, 1.0], order=1)
        >>> pose.valid.tolist()
        [True, True]
        """
        strict = bool_flag("strict", strict)
        from mech.spherical._dual import Dual
        from mech.spherical._transference import dual_fourbar_joints

        order = nonnegative_int("order", order, 1)
        phi12 = finite_array("theta", theta)
        th = phi12 - np.pi
        a, b, c, d = self._twists
        a0, b0, c0, d0 = self._lengths
        A, B, C = _abc.spherical_fourbar_abc(a, b, c, d, th)
        disc = _abc.abc_discriminant(A, B, C)
        valid = disc >= 0.0
        if strict and not np.all(valid):
            bad = float(np.broadcast_to(phi12, valid.shape)[~valid].ravel()[0])
            raise AssemblyError(f"Cannot assemble the RCCC at input angle theta = {bad!r}")
        root = np.sqrt(np.where(valid, disc, np.nan))
        sigma = -self._branch
        psi = _abc.abc_solve(A, B, C, root, sigma)
        psi0 = _gen.rccc_slide(a, b, c, d, a0, b0, c0, d0, self._s1, th, psi)
        psi_hat = Dual(np.where(valid, psi, 0.0), np.where(valid, psi0, 0.0))
        phi23, phi34 = dual_fourbar_joints((a, a0), (c, c0), (d, d0), Dual(th, self._s1), psi_hat)
        middle = {name: np.where(valid, value, np.nan) for name, value in
                  (("phi23", phi23.real_part), ("s2", phi23.dual_part), ("phi34", phi34.real_part), ("s3", phi34.dual_part))}
        fields = {"theta": phi12, "valid": valid, "phi41": np.negative(psi), "s4": np.negative(psi0), **middle}
        if order >= 1:
            omega = finite_array("omega", omega)
            common_shape(theta=phi12, omega=omega)
            # d/dtheta of the coefficients: the dual parts at theta + eps (rule (1))
            dA, dB, dC = (x.dual_part for x in _abc.spherical_fourbar_abc(a, b, c, d, Dual(th, 1.0)))
            # the root vanishes at a limit position: the rates are infinite there
            with np.errstate(divide="ignore", invalid="ignore"):
                dpsi = _abc.abc_rate(dA, dB, dC, psi, root, sigma)
                dpsi0 = _gen.rccc_slide_rate(a, b, c, d, a0, b0, c0, d0, self._s1, th, psi, dpsi)
                fields["omega_output"] = -dpsi * omega
                fields["v_output"] = -dpsi0 * omega
            shape = np.broadcast_shapes(*(np.shape(v) for v in fields.values()))
            fields = {k: np.array(np.broadcast_to(v, shape))[()] for k, v in fields.items()}
            mask_singular_rates(fields, ("omega_output", "v_output"))
        return RCCCPose(order, fields)
