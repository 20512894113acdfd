"""A crank driving a class III group (a triad): the six-bar of example 2-6 (Fig. 2-47).

Links: 1 the crank AB, 2 the rod BC, 3 the ternary link CDE, 4 the rocker DG, 5 the
rocker EF and 6 the frame (pivots A, G, F). The triad 2-3-4-5 has no closed form: its
position is found by Newton's method on three closure equations, and its velocities by
the linear velocity equations (the Jacobian of the same equations).
"""

from dataclasses import dataclass

import numpy as np

from mech._errors import AssemblyError, InputTypeError
from mech._scaling import length_scale
from mech._validate import (
    bool_flag, finite_array, integer, nonnegative_number, planar_point, positive_length, real_number,
)

__all__ = ["TriadPose", "TriadSixBar"]


def _complex_point(name, value):
    return planar_point(name, value)


@dataclass(frozen=True)
class TriadPose:
    """Solved poses of `TriadSixBar` (arrays over the input angles).

    Attributes
    ----------
    theta, valid : ndarray
        Input angles, and False where Newton's method did not converge (NaN there).
    B, C, D, E : ndarray of complex
        Joint positions.
    phi : ndarray, shape (..., 5)
        Angles of links 1 to 5: A->B, B->C, C->D, G->D, F->E.
    omega : ndarray, shape (..., 5)
        Their angular velocities (``omega[..., 0]`` is the input's).
    vB, vC, vD, vE : ndarray of complex
        Joint velocities.
    iterations : ndarray of int
        Newton steps used at each input angle.
    """

    theta: np.ndarray
    valid: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    E: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    vB: np.ndarray
    vC: np.ndarray
    vD: np.ndarray
    vE: np.ndarray
    iterations: np.ndarray


class TriadSixBar:
    """A crank AB driving the triad BC, CDE, DG, EF (class III six-bar, Fig. 2-47).

    Parameters
    ----------
    a, b : float
        Crank AB (about A = 0) and rod BC.
    cd, ce : float
        Sides CD and CE of the ternary link.
    angle : float
        Angle from C->D to C->E, counter-clockwise, radians.
    g, f : float
        Rockers DG and EF.
    G, F : complex
        Frame pivots of the rockers.

    Raises
    ------
    ValueError
        If a length is not positive and finite or a pivot is not finite.

    Notes
    -----
    Unknowns ``q = (x_C, y_C, phi_3)``; equations
    ``|C - B|^2 = b^2``, ``|D - G|^2 = g^2``, ``|E - F|^2 = f^2`` with
    ``D = C + cd exp(i phi_3)``, ``E = C + ce exp(i (phi_3 + angle))``. The assembly mode
    is the one Newton's method reaches from the starting pose; along an array of input
    angles each solution starts the next. Newton's method runs on the lengths and pivots
    divided by a power of two near the largest (`mech._scaling`), so angles do not depend
    on the unit of length. Used on the page :ref:`book-instant-centres`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.kinematics._triad import TriadSixBar
    >>> clamp = TriadSixBar(10, 60, 36, 36, -np.pi / 2, 40, 40, 118 + 41j, 91 - 48j)
    >>> pose = clamp.solve(np.pi / 2, start=(60 + 10j, np.pi / 3))
    >>> bool(pose.valid), round(float(abs(pose.C - pose.B)), 10)
    (True, 60.0)
    """

    def __init__(self, a, b, cd, ce, angle, g, f, G, F):
        self.a, self.b, self.cd, self.ce, self.g, self.f = (
            positive_length(n, v) for n, v in zip(("a", "b", "cd", "ce", "g", "f"), (a, b, cd, ce, g, f)))
        self.angle = real_number("angle", angle)
        self.G, self.F = _complex_point("G", G), _complex_point("F", F)
        self._scale = length_scale(self.a, self.b, self.cd, self.ce, self.g, self.f,
                                   self.G.real, self.G.imag, self.F.real, self.F.imag)
        # Newton's method sees lengths of order one only (see mech._scaling)
        self._unit = tuple(x / self._scale for x in (self.a, self.b, self.cd, self.ce, self.g, self.f,
                                                     self.G, self.F))

    def __repr__(self):
        return (f"TriadSixBar({self.a!r}, {self.b!r}, {self.cd!r}, {self.ce!r}, {self.angle!r}, "
                f"{self.g!r}, {self.f!r}, {self.G!r}, {self.F!r})")

    def _residual(self, q, B):
        """Residuals and Jacobian in the unit lengths of `_unit` (`q` and `B` in those too)."""
        _, b, cd, ce, g, f, G, F = self._unit
        C = q[0] + 1j * q[1]
        eD = np.exp(1j * q[2])
        eE = np.exp(1j * (q[2] + self.angle))
        D, E = C + cd * eD, C + ce * eE
        r = np.array([abs(C - B) ** 2 - b**2, abs(D - G) ** 2 - g**2, abs(E - F) ** 2 - f**2]) / 2
        # rows: d r / d (x_C, y_C, phi_3)
        J = np.array([
            [(C - B).real, (C - B).imag, 0.0],
            [(D - G).real, (D - G).imag, (np.conj(D - G) * 1j * cd * eD).real],
            [(E - F).real, (E - F).imag, (np.conj(E - F) * 1j * ce * eE).real],
        ])
        return r, J, C, D, E

    def solve(self, theta, start, omega=1.0, *, tol=1e-14, max_iter=50, strict=False):
        """Positions by Newton's method and velocities by the linear velocity equations.

        Parameters
        ----------
        theta : array_like, shape (n,) or scalar
            Input angles of A->B, radians, in the order to follow (continuation).
        start : (complex, float)
            Starting pose ``(C, phi_3)`` near the first input angle's solution.
        omega : float, optional
            Input angular velocity, rad/s.
        tol : float, optional
            Stop when the Newton step is below ``tol`` times the linkage size.
        max_iter : int, optional
            Newton steps allowed per input angle.
        strict : bool, optional
            Raise `AssemblyError` instead of returning NaN where it does not converge.

        Returns
        -------
        TriadPose

        Raises
        ------
        AssemblyError
            With ``strict=True``, naming the first input angle that did not converge.
        """
        strict = bool_flag("strict", strict)
        theta = finite_array("theta", theta)
        omega = real_number("omega", omega)
        tol = nonnegative_number("tol", tol)
        max_iter = integer("max_iter", max_iter, minimum=1)
        if not isinstance(start, (tuple, list)) or len(start) != 2:
            raise InputTypeError(f"Expected `start` = (C, phi), a point and an angle, got {start!r}")
        C0 = _complex_point("start[0]", start[0]) / self._scale
        q = np.array([C0.real, C0.imag, real_number("start[1]", start[1])])
        a, b, _, _, g, f, G, F = self._unit
        size = sum(self._unit[:6])
        flat = theta.reshape(-1)
        n = flat.size
        out = {k: np.full(n, np.nan + 0j) for k in ("B", "C", "D", "E", "vB", "vC", "vD", "vE")}
        phi, om = np.full((n, 5), np.nan), np.full((n, 5), np.nan)
        valid, iters = np.zeros(n, bool), np.zeros(n, int)
        for k, t in enumerate(flat):
            B = a * np.exp(1j * t)
            trial = q.copy()
            for it in range(1, max_iter + 1):
                r, J, *_ = self._residual(trial, B)
                step = np.linalg.solve(J, -r) if np.isfinite(np.linalg.cond(J)) else np.full(3, np.nan)
                if not np.all(np.isfinite(step)):
                    break
                trial = trial + step
                if np.max(np.abs(step[:2])) <= tol * size and abs(step[2]) <= tol:
                    break
            r, J, C, D, E = self._residual(trial, B)
            ok = np.all(np.isfinite(trial)) and np.max(np.abs(r)) <= 1e3 * tol * size**2 and it < max_iter
            iters[k] = it
            if not ok:
                if strict:
                    raise AssemblyError(f"Expected the triad to assemble near the previous pose, "
                                        f"got no convergence at theta = {t!r}")
                continue
            q = trial
            vB = 1j * omega * B
            # d r / dt = J q' + (d r / d theta) omega = 0; only |C - B| depends on theta
            rhs = np.array([(np.conj(C - B) * vB).real, 0.0, 0.0])
            qd = np.linalg.solve(J, rhs)
            vC, w3 = qd[0] + 1j * qd[1], qd[2]
            vD, vE = vC + 1j * w3 * (D - C), vC + 1j * w3 * (E - C)
            valid[k] = True
            for name, value in zip(("B", "C", "D", "E", "vB", "vC", "vD", "vE"), (B, C, D, E, vB, vC, vD, vE)):
                out[name][k] = value * self._scale
            phi[k] = [t, np.angle(C - B), trial[2], np.angle(D - G), np.angle(E - F)]
            om[k] = [omega, (np.conj(C - B) * (vC - vB)).imag / b**2, w3,
                     (np.conj(D - G) * vD).imag / g**2, (np.conj(E - F) * vE).imag / f**2]
        shape = theta.shape
        arrays = {k: v.reshape(shape)[()] for k, v in out.items()}
        return TriadPose(theta[()], valid.reshape(shape)[()], arrays["B"], arrays["C"], arrays["D"],
                         arrays["E"], phi.reshape(shape + (5,)), om.reshape(shape + (5,)),
                         arrays["vB"], arrays["vC"], arrays["vD"], arrays["vE"], iters.reshape(shape)[()])
