"""The spherical four-bar: positions, velocities, accelerations, placement on the sphere."""

import numpy as np

from mech import _backend
from mech._scaling import DEAD_POINT_RTOL
from mech._errors import AssemblyError
from mech._generated import spherical_fourbar as _gen
from mech.spherical._fourbar_branch import change_gaps, solve_change_point
from mech._pose import Pose
from mech._pose import AssemblyRange
from mech._validate import (
    arc as _arc, bool_flag, branch_sign, motion_inputs, nonnegative_int, proper_rotation, real_number, real_tuple,
)

__all__ = ["SphericalFourBar", "SphericalFourBarPose", "ground_frame"]

# rows of the reused work array (NumPy backend): the coupler's relative spin, then the
# largest kernel's temporaries
#: The class of `coupler_curve_polynomial` (``[CouplerOctic]``), set by `mech.spherical.path`,
#: which builds on this module: importing any part of `mech.spherical` runs its
#: ``__init__``, which imports the path subpackage, so the entry is there before use.
_COUPLER_POLYNOMIAL = []


def register_coupler_polynomial(cls):
    """Set the class whose ``cls(linkage)`` `SphericalFourBar.coupler_curve_polynomial` returns."""
    _COUPLER_POLYNOMIAL[:] = [cls]
    return cls


_WORK_ROWS = 1 + max(_gen.WORK_ROWS.values())
_VECTORS = {0: ("B", "C", "P"),
            1: ("B", "C", "P", "w_input", "w_coupler", "w_output", "vB", "vC", "vP"),
            2: ("B", "C", "P", "w_input", "w_coupler", "w_output", "vB", "vC", "vP",
                "dw_input", "dw_coupler", "dw_output", "aB", "aC", "aP")}
_SCALARS = {0: ("psi",), 1: ("psi", "omega_output"), 2: ("psi", "omega_output", "alpha_output")}
_RATE_ORDER = {**{k: 1 for k in ("omega_output", "w_input", "w_coupler", "w_output", "vB", "vC", "vP")},
               **{k: 2 for k in ("alpha_output", "dw_input", "dw_coupler", "dw_output", "aB", "aC", "aP")}}


def ground_frame(lon, lat, heading):
    """Rotation that places a spherical four-bar's ground link anywhere on the sphere.

    Returns R with ``R @ (0, 0, 1) = to_xyz(lon, lat)`` (the input pivot A) and the great
    circle A->D leaving A at inclination `heading`: the angle from the local x axis at A
    (along the meridian toward decreasing latitude) counter-clockwise seen from outside.
    With `d` these are the three placement parameters of the nine-parameter linkage.

    Parameters
    ----------
    lon, lat, heading : float
        Longitude and latitude of A (``to_xyz(lon, lat) = (cos lat cos lon,
        cos lat sin lon, sin lat)``) and the inclination of A->D, radians.

    Returns
    -------
    ndarray, shape (3, 3)
        Columns: the direction of A->D at A, the direction 90 degrees counter-clockwise
        from it, and A.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._fourbar import ground_frame
    >>> np.allclose(ground_frame(0.0, np.pi / 2, 0.0), np.eye(3))
    True
    >>> np.round(ground_frame(0.3, 0.2, 1.0)[:, 2], 6).tolist()
    [0.936293, 0.289629, 0.198669]
    """
    lon, lat, heading = (real_number(n, v) for n, v in (("lon", lon), ("lat", lat), ("heading", heading)))
    if not -np.pi / 2 <= lat <= np.pi / 2:
        raise ValueError(f"Expected `lat` in [-pi/2, pi/2], got {lat!r}")
    cl, sl, co, so = np.cos(lat), np.sin(lat), np.cos(lon), np.sin(lon)
    x = np.array([sl * co, sl * so, -cl])
    y = np.array([-so, co, 0.0])
    A = np.array([cl * co, cl * so, sl])
    ch, sh = np.cos(heading), np.sin(heading)
    return np.column_stack((ch * x + sh * y, -sh * x + ch * y, A))


class SphericalFourBarPose(Pose):
    """Poses of a spherical four-bar at an array of input angles (`SphericalFourBar.solve`).

    Attributes
    ----------
    theta, psi, valid : ndarray, shape (...)
        Input angle, output angle in (-pi, pi] (NaN where it cannot assemble) and the mask.
    B, C, P : ndarray, shape (..., 3)
        Unit vectors of the pins and of the coupler point.
    omega_output, w_input, w_coupler, w_output, vB, vC, vP : ndarray
        d psi/dt, the angular velocity vectors (..., 3) of the three moving links and the
        point velocities; present when solved with ``order >= 1``.
    alpha_output, dw_input, dw_coupler, dw_output, aB, aC, aP : ndarray
        The second-order counterparts; present when solved with ``order >= 2``.
    """

    _ORDER_OF = {**{k: 1 for k in ("omega_output", "w_input", "w_coupler", "w_output", "vB", "vC", "vP")},
                 **{k: 2 for k in ("alpha_output", "dw_input", "dw_coupler", "dw_output", "aB", "aC", "aP")}}


class SphericalFourBar:
    """A spherical four-bar (球面四杆机构): four revolute axes through the sphere's centre.

    Parameters
    ----------
    a, b, c, d : float
        Arcs AB (input), BC (coupler), CD (output) and AD (ground), radians in (0, pi).
    branch : {1, -1}, optional
        Assembly branch: +1 where ``det[B, D, C] > 0``.
    coupler : (float, float), optional
        Coupler point ``(r, gamma)``: at arc `r` from B, at the angle `gamma` counter-
        clockwise (seen from outside) from the great circle B->C. ``(0, 0)`` puts P at B.
    frame : array_like, shape (3, 3), optional
        Proper rotation placing the linkage: every point is ``frame @`` its position in
        the default frame (A = (0, 0, 1), D = (sin d, 0, cos d)). See `ground_frame`.
    rtol : float, optional
        Relative tolerance (of a + b + c + d) within which a gap of the arc BD to the
        ends of its window counts as zero, making this a change-point linkage.

    Raises
    ------
    ValueError
        If an arc is not in (0, pi), `branch` is not +1 or -1, `coupler` is not two finite
        numbers, `frame` is not a proper rotation, or `rtol` is not in [0, 1e-3).

    Notes
    -----
    Derivation: :ref:`deriv-spherical-fourbar`. theta is the angle at A from A->D to A->B
    and psi the angle at D from A->D continued to D->C, both counter-clockwise seen from
    outside; as the arcs shrink the linkage becomes `mech.planar.FourBar` with
    ``coupler=(r cos gamma, r sin gamma)``, point for point in the tangent plane at A.
    Along a branch psi is continuous in theta; at a limit position (the ends of
    `assembly_range`) the two branches meet, and the rates are unbounded there. A
    change-point linkage (`change_point`: deltoids, isograms, rhombi, all arcs pi/2 and
    their antipodal forms, any s + l = p + q) has its branches meet at theta = 0 or pi with
    the four joints on one great circle; there the motion continues smoothly onto the other
    sign of det[B, D, C] (a parallel isogram stays parallel), positions and rates
    continuous, and `branch` names the branch on 0 < theta < pi. A linkage with one such
    angle returns to its first branch after two input turns. Where B passes through D
    (a = d, b = c) or through -D (a + d = b + c = pi) the pose is the limit along the
    branch. Change-point linkages are solved by the half-angle form, eqs. (11)-(13) of
    :ref:`deriv-spherical-fourbar`, with exact theta-derivatives for the rates.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._fourbar import SphericalFourBar
    >>> linkage = SphericalFourBar(0.3, 0.9, 0.7, 1.0)
    >>> pose = linkage.solve(np.pi / 2)
    >>> round(float(np.arccos(pose.B @ pose.C)), 12), round(float(pose.psi), 6)
    (0.9, 1.64216)
    >>> linkage.solve(np.linspace(0, np.pi, 5), order=1).w_coupler.shape
    (5, 3)
    """

    def __init__(self, a, b, c, d, *, branch=1, coupler=(0.0, 0.0), frame=None, rtol=1e-12):
        self._a, self._b, self._c, self._d = (_arc(n, v) for n, v in zip("abcd", (a, b, c, d)))
        rtol = real_number("rtol", rtol)
        if not 0.0 <= rtol < 1e-3:
            raise ValueError(f"Expected `rtol` in [0, 1e-3), got {rtol!r}")
        self._gaps = change_gaps(self._a, self._b, self._c, self._d, rtol)
        self._branch = branch_sign(branch)
        self._coupler = real_tuple("coupler", coupler, 2)
        self._frame = None if frame is None else proper_rotation("frame", frame)

    a = property(lambda self: self._a, doc="Input arc AB.")
    b = property(lambda self: self._b, doc="Coupler arc BC.")
    c = property(lambda self: self._c, doc="Output arc CD.")
    d = property(lambda self: self._d, doc="Ground arc AD.")
    branch = property(lambda self: self._branch, doc="Assembly branch, +1 or -1.")
    coupler = property(lambda self: self._coupler, doc="Coupler point (r, gamma).")
    frame = property(lambda self: None if self._frame is None else self._frame.copy(),
                     doc="Placement rotation, or None for the default frame.")

    @property
    def change_point(self):
        """True if the two branches meet at theta = 0 or pi (a gap within `rtol` of zero)."""
        return any(g == 0.0 for g in self._gaps.values())

    @property
    def A(self):
        """The input pivot A, shape (3,)."""
        return self._place(np.array([0.0, 0.0, 1.0]))

    @property
    def D(self):
        """The output pivot D, shape (3,)."""
        return self._place(np.array([np.sin(self._d), 0.0, np.cos(self._d)]))

    def _place(self, v):
        return v if self._frame is None else v @ self._frame.T

    def __repr__(self):
        extra = "" if self._frame is None else ", frame=..."
        return (f"SphericalFourBar({self._a!r}, {self._b!r}, {self._c!r}, {self._d!r}, "
                f"branch={self._branch}, coupler={self._coupler!r}{extra})")

    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Solve the spherical four-bar at the input angles `theta`.

        Positions by the atan2 root of A cos(psi) + B sin(psi) = C with a cancellation-
        free C; rates from the two joint constraints of the coupler (eqs. (1)-(10) of
        :ref:`deriv-spherical-fourbar`).

        Parameters
        ----------
        theta : array_like, shape (...)
            Input angle at A from A->D to A->B, counter-clockwise from outside, radians.
        order : {0, 1, 2}, optional
            Highest time derivative to compute; nothing above it is computed.
        omega, alpha : array_like, optional
            Angular velocity and acceleration of the input link, broadcast against `theta`.
            Any finite values: rates are solved for them scaled to at most 1 and scaled
            back, so a rate beyond the float range is +-inf, never NaN.
        strict : bool, optional
            Raise `AssemblyError` instead of returning NaN where it cannot assemble.

        Returns
        -------
        SphericalFourBarPose
            ``theta, psi, valid`` and ``B, C, P`` (shape (..., 3)); with ``order >= 1``
            also ``omega_output, w_input, w_coupler, w_output, vB, vC, vP``; with
            ``order >= 2`` also ``alpha_output, dw_input, dw_coupler, dw_output, aB, aC, aP``.

        Raises
        ------
        AssemblyError
            With ``strict=True``, naming the first input angle that cannot be assembled
            and the input range where the linkage assembles.
        ValueError
            For a non-finite `theta`, `omega` or `alpha`, or an `order` outside 0..2.

        Examples
        --------
        >>> from mech.spherical._fourbar import SphericalFourBar
        >>> pose = SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.5)).solve([0.0, 1.0], order=2)
        >>> pose.valid.tolist(), pose.aP.shape
        ([True, True], (2, 3))
        """
        strict = bool_flag("strict", strict)
        order, shape, inputs = motion_inputs("theta", theta, order, omega, alpha)
        flat = [x.reshape(-1) for x in inputs]
        size = flat[0].size
        # rates are solved for omega / m and alpha / m^2 (m = max(|omega|, sqrt|alpha|)),
        # then scaled back: no overflow inside, and a rate beyond the float range is +-inf
        if order >= 1:
            m = np.abs(flat[1]) if order == 1 else np.maximum(np.abs(flat[1]), np.sqrt(np.abs(flat[2])))
            m = np.where(m > 0.0, m, 1.0)
            flat[1] = flat[1] / m
            if order >= 2:
                flat[2] = flat[2] / m / m
        out = {name: np.empty((size, 3)) for name in _VECTORS[order]}
        out.update({name: np.empty(size) for name in _SCALARS[order]})
        # numba: fused loops over NUMBA_BLOCK points at a time; NumPy: cache-sized blocks
        # with reused work rows
        numba = _backend.use_numba(size) and not self.change_point
        step = _backend.NUMBA_BLOCK if numba else _backend.BLOCK
        for start in range(0, max(size, 1), step):
            block = slice(start, start + step)
            self._solve_block([x[block] for x in flat], order, {k: v[block] for k, v in out.items()}, numba)
        if order >= 1:
            with np.errstate(over="ignore"):
                for name, value in out.items():
                    power = _RATE_ORDER.get(name, 0)
                    scale = m if value.ndim == 1 else m[:, None]
                    for _ in range(power):
                        value *= scale
        valid = ~np.isnan(out["psi"])
        if strict and not np.all(valid):
            bad = float(flat[0][~valid][0])
            raise AssemblyError(f"Cannot assemble {self!r} at theta = {bad!r}; {_describe(self.assembly_range())}")
        if self._frame is not None:
            for name in _VECTORS[order]:
                out[name] = out[name] @ self._frame.T
        fields = {name: value.reshape(shape + (3,)) for name, value in out.items() if name in _VECTORS[order]}
        fields.update({name: out[name].reshape(shape)[()] for name in _SCALARS[order]})
        fields["valid"] = valid.reshape(shape)[()]
        fields["theta"] = np.broadcast_to(theta, shape)[()]
        return SphericalFourBarPose(order, fields)

    def _solve_block(self, inputs, order, out, numba=False):
        """Solve one block of flat inputs in the default frame, writing into `out`.

        The generated kernels write straight into the columns of the output arrays; the
        NumPy ones keep their temporaries in one work array reused by every block.
        """
        a, b, c, d, (r, gamma) = self._a, self._b, self._c, self._d, self._coupler
        theta = inputs[0]
        if self.change_point:
            self._solve_change_block(inputs, order, out)
            return
        n = theta.shape[0]
        kernels = _backend.numba_kernels("spherical_fourbar") if numba else None
        work = None if numba else _backend.workspace("spherical", _WORK_ROWS, n)

        def run(name, args, outs):
            if numba:
                getattr(kernels, f"{name}_kernel")(*args, *outs)
            else:
                getattr(_gen, f"{name}_into")(*args, outs, work[1:1 + _gen.WORK_ROWS[name]])

        # over: 1 / |B x D|^2 where B all but meets D (a = d, theta ~ 1e-160) cannot assemble
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            points = tuple(out[name][:, k] for name in "BCP" for k in range(3))
            run("spherical_fourbar_position", (a, b, c, d, r, gamma, theta, -self._branch),
                (out["psi"],) + points)
            if order < 1:
                self._dead_points(theta, out)
                return
            omega = inputs[1]
            lam = np.empty(n) if numba else work[0]       # row 0: the coupler's relative spin
            run("spherical_fourbar_velocity", (d, *points, omega),
                (out["omega_output"], lam) + tuple(out[name][:, k] for name in ("w_coupler", "w_output", "vB", "vC", "vP")
                                                   for k in range(3)))
            win = out["w_input"]
            win[:, 0] = 0.0
            win[:, 1] = 0.0
            win[:, 2] = omega
            if order < 2:
                return
            alpha = inputs[2]
            run("spherical_fourbar_acceleration", (d, *points, omega, alpha, out["omega_output"], lam),
                (out["alpha_output"],) + tuple(out[name][:, k] for name in ("dw_coupler", "dw_output", "aB", "aC", "aP")
                                               for k in range(3)))
            dwin = out["dw_input"]
            dwin[:, 0] = 0.0
            dwin[:, 1] = 0.0
            dwin[:, 2] = alpha

    def _dead_points(self, theta, out):
        """Positions within `DEAD_POINT_RTOL` (a + b + c + d) of a dead point are the dead point.

        A dead point is where the arc BD is b + c or |b - c|: C lies on the great circle
        through B and D. Whether a float input there assembles is decided by a rounding, which
        the same linkage at another input a few ulps away decides the other way; within the
        band the pose that did not assemble is the dead point's (C on the arc BD, at arc b
        from B), as the planar solvers give it. Positions only: the rates are unbounded there.
        """
        miss = np.flatnonzero(np.isnan(out["psi"]))
        if miss.size == 0:
            return
        a, b, c, d, (r, gamma) = self._a, self._b, self._c, self._d, self._coupler
        th = theta[miss]
        B = np.stack([np.sin(a) * np.cos(th), np.sin(a) * np.sin(th), np.full(th.shape, np.cos(a))], axis=-1)
        D = np.array([np.sin(d), 0.0, np.cos(d)])
        sin_k = np.linalg.norm(np.cross(B, D), axis=-1)
        k = np.arctan2(sin_k, B @ D)                                 # the arc BD, well conditioned
        tol = DEAD_POINT_RTOL * (a + b + c + d)
        far = np.abs(k - (b + c)) <= tol
        close = np.abs(k - abs(b - c)) <= tol
        snap = (far | close) & (sin_k > 0.0)
        if not snap.any():
            return
        B, k, sin_k = B[snap], k[snap], sin_k[snap]
        # C on the great circle BD at arc b from B: towards D, or away from it when c > b
        sb = np.where(far[snap] | (b >= c), b, -b)
        C = (np.sin(k - sb)[:, None] * B + np.sin(sb)[:, None] * D) / sin_k[:, None]
        C /= np.linalg.norm(C, axis=-1, keepdims=True)
        t = C - np.sum(B * C, axis=-1, keepdims=True) * B
        t /= np.linalg.norm(t, axis=-1, keepdims=True)
        P = np.cos(r) * B + np.sin(r) * (np.cos(gamma) * t + np.sin(gamma) * np.cross(B, t))
        rows = miss[snap]
        out["B"][rows], out["C"][rows], out["P"][rows] = B, C, P
        out["psi"][rows] = np.arctan2(C[:, 1], np.cos(d) * C[:, 0] - np.sin(d) * C[:, 2])

    def _solve_change_block(self, inputs, order, out):
        """`_solve_block` for a change-point linkage: the smooth closed form, whose exact
        theta-derivatives give the rates (see `mech.spherical._fourbar_branch`)."""
        theta = inputs[0]
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            psi, B, C, P = solve_change_point((self._a, self._b, self._c, self._d), self._coupler,
                                              self._gaps, theta, self._branch, order)
            ok = np.isfinite(psi.v)
            for k in range(3):
                for name, jet in (("B", B[k]), ("C", C[k]), ("P", P[k])):
                    out[name][:, k] = np.where(ok, jet.v, np.nan)
            # (-pi, pi], as atan2 gives it
            out["psi"][...] = np.where(ok, np.pi - np.mod(np.pi - psi.v, 2 * np.pi), np.nan)
            if order < 1:
                return
            omega = inputs[1]
            out["omega_output"][...] = psi.d1 * omega
            D = np.array([np.sin(self._d), 0.0, np.cos(self._d)])
            out["w_input"][...] = 0.0
            out["w_input"][:, 2] = omega
            out["w_output"][...] = out["omega_output"][:, None] * D
            Bv, Cv = (np.stack([x.v for x in X], axis=-1) for X in (B, C))
            dB, dC = (np.stack([x.d1 for x in X], axis=-1) for X in (B, C))
            for name, X in (("vB", B), ("vC", C), ("vP", P)):
                for k in range(3):
                    out[name][:, k] = X[k].d1 * omega
            # the coupler spins about B at lam = omega * Lam relative to the input link:
            # C' = A x C + Lam B x C, so Lam = (C' - A x C) . (B x C) / sin^2 b
            ez = np.array([0.0, 0.0, 1.0])
            BxC = np.cross(Bv, Cv)
            rel = dC - np.cross(ez, Cv)
            sb2 = np.sin(self._b) ** 2
            Lam = np.sum(rel * BxC, axis=-1) / sb2
            lam = omega * Lam
            out["w_coupler"][...] = omega[:, None] * ez + lam[:, None] * Bv
            if order < 2:
                return
            alpha = inputs[2]
            w2 = omega * omega
            out["alpha_output"][...] = psi.d2 * w2 + psi.d1 * alpha
            out["dw_input"][...] = 0.0
            out["dw_input"][:, 2] = alpha
            out["dw_output"][...] = out["alpha_output"][:, None] * D
            for name, X in (("aB", B), ("aC", C), ("aP", P)):
                for k in range(3):
                    out[name][:, k] = X[k].d2 * w2 + X[k].d1 * alpha
            ddC = np.stack([x.d2 for x in C], axis=-1)
            dBxC = np.cross(dB, Cv) + np.cross(Bv, dC)
            dLam = (np.sum((ddC - np.cross(ez, dC)) * BxC, axis=-1) + np.sum(rel * dBxC, axis=-1)) / sb2
            dlam = alpha * Lam + w2 * dLam
            out["dw_coupler"][...] = (alpha[:, None] * ez + dlam[:, None] * Bv
                                      + (lam * omega)[:, None] * np.cross(ez, Bv))

    def assembly_range(self):
        """The input angles where the linkage assembles; its ends are limit positions.

        The arc g = BD grows with ``|theta|`` from ``|a - d|`` to min(a + d, 2 pi - a - d); the
        linkage assembles while g lies in [``|b - c|``, min(b + c, 2 pi - b - c)] (the
        triangle BCD closes). The ends come from eq. (6) of :ref:`deriv-spherical-fourbar`.

        Returns
        -------
        mech.spatial.AssemblyRange
            ``intervals`` of theta (limit positions at the ends) and ``full_turn``.

        Examples
        --------
        >>> from mech.spherical._fourbar import SphericalFourBar
        >>> SphericalFourBar(0.3, 0.9, 0.7, 1.0).assembly_range().full_turn
        True
        >>> rng = SphericalFourBar(0.8, 0.5, 0.55, 0.7).assembly_range()
        >>> rng.full_turn, rng.intervals.shape
        (False, (1, 2))
        """
        a, b, c, d = self._a, self._b, self._c, self._d
        g_lo, g_hi = abs(a - d), min(a + d, 2 * np.pi - a - d)
        w_lo, w_hi = abs(b - c), min(b + c, 2 * np.pi - b - c)
        lo, hi = max(g_lo, w_lo), min(g_hi, w_hi)
        if lo > hi:
            return AssemblyRange(np.empty((0, 2)), False)
        t_lo = 0.0 if w_lo <= g_lo else float(_gen.spherical_fourbar_limit_theta(a, d, lo))
        t_hi = np.pi if w_hi >= g_hi else float(_gen.spherical_fourbar_limit_theta(a, d, hi))
        if t_lo == 0.0 and t_hi == np.pi:
            return AssemblyRange(np.empty((0, 2)), True)
        if t_lo == 0.0:
            intervals = [(-t_hi, t_hi)]
        elif t_hi == np.pi:
            intervals = [(t_lo, 2 * np.pi - t_lo)]
        else:
            intervals = [(-t_hi, -t_lo), (t_lo, t_hi)]
        return AssemblyRange(np.array(intervals, dtype=float), False)

    def coupler_curve_polynomial(self):
        """The implicit coupler curve: the homogeneous octic F in (x, y, z) (monograph §2.1).

        Returns a `mech.spherical.path.CouplerOctic`: call it on points of shape (..., 3)
        for F and its gradient (the cone over the curve and over its antipodal image,
        degree 8). Other forms: ``.quartic`` (the quartic Q that cuts the curve from the
        sphere), ``.lonlat`` (Q in longitude and latitude), and the parametric form
        `solve` (P, vP, aP over theta). Both assembly branches lie on the one curve; the
        mirrored coupler point ``(r, -gamma)`` does not. Derivation:
        :ref:`deriv-spherical-coupler-curve`.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spherical._fourbar import SphericalFourBar
        >>> m = SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.6, 0.8), branch=-1)
        >>> F, grad = m.coupler_curve_polynomial()(m.solve([0.5, 2.0]).P)
        >>> bool(np.all(np.abs(F) < 1e-12 * np.linalg.norm(grad, axis=-1)))
        True
        """
        return _COUPLER_POLYNOMIAL[0](self)

    def coupler_curve(self, n=721):
        """The coupler point over the assembly range on this branch, for figures.

        Returns ``(theta, P)``: `n` input angles over the full turn, or spread over the
        intervals of `assembly_range` with a NaN row between intervals, and P there,
        shape (n', 3).

        Examples
        --------
        >>> from mech.spherical._fourbar import SphericalFourBar
        >>> theta, P = SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.5)).coupler_curve(50)
        >>> P.shape
        (50, 3)
        """
        n = nonnegative_int("n", n, 10**8)
        rng = self.assembly_range()
        if rng.full_turn:
            theta = np.linspace(-np.pi, np.pi, n)
        else:
            pieces = []
            total = float(np.sum(rng.intervals[:, 1] - rng.intervals[:, 0])) or 1.0
            for start, end in rng.intervals:
                count = max(2, int(round(n * (end - start) / total)))
                inset = 1e-10 * (end - start)          # the exact ends round to either side of w = 0
                pieces += [np.linspace(start + inset, end - inset, count), [np.nan]]
            theta = np.concatenate(pieces[:-1]) if pieces else np.empty(0)
        ok = np.isfinite(theta)
        P = np.full(theta.shape + (3,), np.nan)
        P[ok] = self.solve(theta[ok]).P
        return theta, P


def _describe(rng):
    """Words for an AssemblyRange, for error messages."""
    if rng.full_turn:
        return "it assembles at every input angle"
    if rng.intervals.size == 0:
        return "it assembles at no input angle"
    parts = ", ".join(f"[{s:.6g}, {e:.6g}]" for s, e in rng.intervals)
    return f"it assembles for theta in {parts} (radians)"
