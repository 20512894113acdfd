"""Open chains of R, P, C and H pairs described by H-D parameters, eqs. (2-73) and (2-74).

A chain of n joints carries frames 0 (the ground) to n (the end link). Joint k joins link
k-1 and link k; its axis is z_{k-1}, and M_{k-1,k} = hd(phi, lam, s, h) (2-67) with the
joint variable added to phi (R, H, C), to s (P, C), or to both (H: s grows by pitch / 2 pi
per radian). The end pose is M_0n = M_01 M_12 ... M_{n-1,n} (2-73), (2-74).
"""

import math
from dataclasses import dataclass

import numpy as np

from mech import _backend
from mech._errors import InputTypeError
from mech._generated import open_chains as _gen
from mech._pose import Pose
from mech._scaling import length_scale_array
from mech._validate import finite_array, nonnegative_int, option, positive_length, real_number
from mech.spatial._transforms import hd

__all__ = ["Joint", "OpenChain", "ChainPose", "example_2_25_manipulator", "example_2_25_pose",
           "example_2_25_reach"]

_KINDS = {"R": 1, "P": 1, "C": 2, "H": 1}
#: Poses per block of a large solve: the block's 4 x 4 products and their temporaries stay
#: in cache (measured in benchmarks/bench_speed_linkage.py).
_BLOCK = 4096
#: The smallest solve that the backend ``"auto"`` hands to the compiled loop
#: (`mech.spatial._chain_compiled`), as for the planar `Linkage`: at 10^3 poses the NumPy
#: path cost 9 times a plain compiled loop (benchmarks/bench_compiled.py), the loop far less.
_COMPILED_MIN_SIZE = 512


@dataclass(frozen=True)
class Joint:
    """One pair of an open chain with the fixed H-D parameters of M_{k-1,k}.

    Parameters
    ----------
    kind : {"R", "P", "C", "H"}
        Revolute (variable phi), prismatic (variable s), cylindrical (variables phi, s) or
        helical (variable phi, with s = s0 + pitch * phi / (2 pi)).
    phi, lam, s, h : float
        The H-D parameters of (2-67); for a variable the value here is an offset that the
        joint variable is added to.
    pitch : float
        Lead of a helical pair per turn (length); must be 0 for the other kinds.
    """

    kind: str
    phi: float = 0.0
    lam: float = 0.0
    s: float = 0.0
    h: float = 0.0
    pitch: float = 0.0

    def __post_init__(self):
        option("kind", self.kind, sorted(_KINDS))
        for name in ("phi", "lam", "s", "h", "pitch"):
            object.__setattr__(self, name, real_number(name, getattr(self, name)))
        if self.kind != "H" and self.pitch != 0.0:
            raise ValueError(f"Expected `pitch` = 0 for a {self.kind} pair, got {self.pitch!r}")

    @property
    def dof(self):
        """Number of joint variables (2 for a C pair, 1 otherwise)."""
        return _KINDS[self.kind]

    @property
    def weights(self):
        """(dphi/dq, ds/dq) of the pair for each of its variables, as two tuples."""
        lead = self.pitch / (2.0 * np.pi)
        return {"R": ((1.0,), (0.0,)), "P": ((0.0,), (1.0,)), "H": ((1.0,), (lead,)),
                "C": ((1.0, 0.0), (0.0, 1.0))}[self.kind]


class ChainPose(Pose):
    """Immutable pose of the end of an open chain (returned by `OpenChain.solve`).

    Attributes
    ----------
    M : ndarray, shape (..., 4, 4)
        M_0n, the end frame in the ground frame (2-73).
    P : ndarray, shape (..., 3)
        The end point (x0, y0, z0) in the ground frame.
    e1, e2, e3 : ndarray, shape (..., 3)
        Unit vectors x_n, y_n, z_n of the end frame: e1 = (l, m, n), e3 = (u, v, w) (2-74).
    vP, omega : ndarray, shape (..., 3)
        Velocity of P and angular velocity of the end link (``order >= 1``).
    aP, alpha : ndarray, shape (..., 3)
        Acceleration of P and angular acceleration of the end link (``order >= 2``).
    """

    _ORDER_OF = {"vP": 1, "omega": 1, "aP": 2, "alpha": 2}

    def __repr__(self):
        return f"ChainPose(order={self.order}, shape={self._fields['P'].shape[:-1]})"


class OpenChain:
    """An open chain of R, P, C and H pairs given by H-D parameters, eqs. (2-73), (2-74).

    Parameters
    ----------
    joints : sequence of Joint
        Joint k joins link k-1 to link k; its axis is z_{k-1}.

    Attributes
    ----------
    joints : tuple of Joint
    dof : int
        Number of joint variables (a C pair counts two).

    Notes
    -----
    Velocities and accelerations come from differentiating the product (2-73): each joint
    adds phi' z_{k-1} to the angular velocity and moves the next origin by
    omega_k x r + s' z_{k-1}; derived and checked in :ref:`deriv-open-chains`
    (``derivations/spatial/open_chains.md``).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._chain import Joint, OpenChain
    >>> arm = OpenChain([Joint("R", h=1.0), Joint("R", h=1.0)])     # planar two-link arm
    >>> np.round(arm.solve([0.0, np.pi / 2]).P, 12)
    array([1., 1., 0.])
    """

    def __init__(self, joints):
        if isinstance(joints, (str, bytes)) or not hasattr(joints, "__iter__"):
            raise InputTypeError(f"Expected `joints` to be a non-empty sequence of Joint, got {joints!r}")
        joints = tuple(joints)
        if not joints or not all(isinstance(j, Joint) for j in joints):
            raise ValueError(f"Expected `joints` to be a non-empty sequence of Joint, got {joints!r}")
        self.joints = joints
        self.dof = sum(j.dof for j in joints)

    def __repr__(self):
        return "OpenChain(" + "".join(j.kind for j in self.joints) + ")"

    def _split(self, name, value):
        arr = finite_array(name, value)
        if arr.ndim == 0 or arr.shape[-1] != self.dof:
            raise ValueError(f"Expected `{name}` with last axis {self.dof}, got shape {arr.shape}")
        return arr

    def _joint_values(self, q, qd, qdd):
        """Per joint: phi, s and their first and second time derivatives (None if zero)."""
        out, k = [], 0
        for joint in self.joints:
            w_phi, w_s = joint.weights
            cols = range(k, k + joint.dof)
            k += joint.dof

            def combine(x, w):
                terms = [] if x is None else [w_i * x[..., c] for w_i, c in zip(w, cols) if w_i != 0.0]
                return sum(terms) if terms else None

            phi, s = combine(q, w_phi), combine(q, w_s)
            phi = joint.phi if phi is None else joint.phi + phi
            s = joint.s if s is None else joint.s + s
            out.append((joint, phi, s, combine(qd, w_phi), combine(qd, w_s), combine(qdd, w_phi),
                        combine(qdd, w_s)))
        return out

    def solve(self, q, order=0, qdot=None, qddot=None, *, point=(0.0, 0.0, 0.0)):
        """Pose of the end link, and its rates, at joint values `q`, eqs. (2-73), (2-74).

        Parameters
        ----------
        q : array_like, shape (..., dof)
            Joint variables in chain order (angles in radians, slides in length units;
            a C pair takes two entries, angle then slide).
        order : {0, 1, 2}
            0: pose; 1: also velocities; 2: also accelerations.
        qdot, qddot : array_like, shape (..., dof), optional
            Joint rates; `qdot` is required for ``order >= 1``, `qddot` defaults to zero.
        point : array_like, shape (3,)
            The end point P in frame n.

        Returns
        -------
        ChainPose
            ``M``, ``P``, ``e1``, ``e2``, ``e3``; with ``order >= 1`` also ``vP`` and
            ``omega``; with ``order >= 2`` also ``aP`` and ``alpha``. All in frame 0.

        Raises
        ------
        ValueError
            If a value is not finite, a shape does not end in ``dof``, or `qdot` is missing.

        Notes
        -----
        More than 4096 poses are solved in blocks of that many, each while its 4 x 4
        products stay in the cache, with the same results. With numba installed, the backend
        ``"auto"`` (from 512 poses) or ``"numba"`` solves them instead in one compiled loop
        (`mech.spatial._chain_compiled`), within a few ulp of the NumPy path.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spatial._chain import Joint, OpenChain
        >>> screw = OpenChain([Joint("H", pitch=2.0)])
        >>> pose = screw.solve([np.pi], order=1, qdot=[1.0], point=(1.0, 0.0, 0.0))
        >>> np.round(pose.P, 12), np.round(pose.vP, 12)
        (array([-1.,  0.,  1.]), array([-0.      , -1.      ,  0.31831]))
        """
        order = nonnegative_int("order", order, 2)
        q = self._split("q", q)
        if order >= 1 and qdot is None:
            raise ValueError("Expected `qdot` for order >= 1, got None")
        qd = self._split("qdot", qdot) if order >= 1 else None
        qdd = None
        if order >= 2:
            qdd = self._split("qddot", np.zeros(self.dof) if qddot is None else qddot)
        shape = np.broadcast_shapes(*(x.shape[:-1] for x in (q, qd, qdd) if x is not None))
        q, qd, qdd = (None if x is None else np.broadcast_to(x, shape + (self.dof,)) for x in (q, qd, qdd))
        point = finite_array("point", point)
        if point.shape != (3,):
            raise ValueError(f"Expected `point` of shape (3,), got {point.shape}")
        size = math.prod(shape)
        if _backend.use_numba(size, _COMPILED_MIN_SIZE):
            from mech.spatial import _chain_compiled     # imports numba: only when a solve uses it

            return ChainPose(order, _chain_compiled.solve_fields(self, q, qd, qdd, order, point, shape))
        if size <= _BLOCK:
            return ChainPose(order, self._solve_fields(q, qd, qdd, order, point, shape))
        # cache-sized blocks, each solved whole and copied into outputs allocated once: no
        # temporary outlives its block (every pose depends on its own joint values only)
        flat = [None if x is None else x.reshape(size, self.dof) for x in (q, qd, qdd)]
        out = {}
        for start in range(0, size, _BLOCK):
            part = slice(start, start + _BLOCK)
            fields = self._solve_fields(*(None if x is None else x[part] for x in flat), order, point,
                                        (min(size, part.stop) - start,))
            for name in ("M", "P", "vP", "omega", "aP", "alpha"):
                if name in fields:
                    if name not in out:
                        out[name] = np.empty((size,) + fields[name].shape[1:])
                    out[name][part] = fields[name]
        fields = {name: value.reshape(shape + value.shape[1:]) for name, value in out.items()}
        T = fields["M"]
        fields.update(e1=T[..., :3, 0], e2=T[..., :3, 1], e3=T[..., :3, 2])
        return ChainPose(order, fields)

    def _solve_fields(self, q, qd, qdd, order, point, shape):
        """The fields of `solve` for joint values broadcast to ``shape + (dof,)``."""
        T = np.broadcast_to(np.eye(4), shape + (4, 4))
        zero = np.zeros(shape + (3,))
        omega, v, alpha, a = zero, zero, zero, zero
        for joint, phi, s, dphi, ds, ddphi, dds in self._joint_values(q, qd, qdd):
            z, o = T[..., :3, 2], T[..., :3, 3]
            T = T @ hd(phi, joint.lam, s, joint.h)
            r = T[..., :3, 3] - o
            if order >= 1:
                dphi, ds = ((np.zeros(shape) if x is None else x)[..., None] for x in (dphi, ds))
                omega_new = omega + dphi * z
                v_new = v + np.cross(omega_new, r) + ds * z
            if order >= 2:
                ddphi, dds = ((np.zeros(shape) if x is None else x)[..., None] for x in (ddphi, dds))
                zdot = np.cross(omega, z)
                alpha = alpha + ddphi * z + dphi * zdot
                a = a + np.cross(alpha, r) + np.cross(omega_new, v_new - v) + dds * z + ds * zdot
            if order >= 1:
                omega, v = omega_new, v_new
        T = np.ascontiguousarray(T)
        d = T[..., :3, :3] @ point
        fields = {"M": T, "P": T[..., :3, 3] + d, "e1": T[..., :3, 0], "e2": T[..., :3, 1], "e3": T[..., :3, 2]}
        if order >= 1:
            fields.update(vP=v + np.cross(omega, d), omega=omega)
        if order >= 2:
            fields.update(aP=a + np.cross(alpha, d) + np.cross(omega, np.cross(omega, d)), alpha=alpha)
        return fields

    def frames(self, q):
        """Every link frame in the ground frame: M_00 = I, M_01, M_02, ..., M_0n.

        Parameters
        ----------
        q : array_like, shape (..., dof)
            Joint variables, as in `solve`.

        Returns
        -------
        ndarray, shape (..., n + 1, 4, 4)
            The prefixes of the product (2-73), e.g. to draw the chain.

        Examples
        --------
        >>> from mech.spatial._chain import example_2_25_manipulator
        >>> example_2_25_manipulator(0.5).frames([0.1, 0.2, 0.3, 0.4]).shape
        (5, 4, 4)
        """
        q = self._split("q", q)
        T = np.broadcast_to(np.eye(4), q.shape[:-1] + (4, 4))
        out = [T]
        for joint, phi, s, *_ in self._joint_values(q, None, None):
            T = T @ hd(phi, joint.lam, s, joint.h)
            out.append(T)
        return np.stack(out, axis=-3)

    def pose(self, q, *, point=(0.0, 0.0, 0.0)):
        """Position and orientation of the end link: ``solve(q, order=0, point=point)``."""
        return self.solve(q, 0, point=point)


def example_2_25_manipulator(s0):
    """The four-joint manipulator of example 2-25 (Fig. 2-125) as an `OpenChain`.

    Joints R (phi01, twist 90 deg, S0 = l_AB), R (phi12, twist 90 deg), P (S2 = CB) and
    R (phi34): an RRPR chain (the textbook's title and figure call it PRPR, but by its own
    description only the pair between links 2 and 3 slides). Joint variables
    ``q = (phi01, phi12, S2, phi34)``.

    Parameters
    ----------
    s0 : float
        Height S0 = l_AB of the shoulder B above the base origin A, > 0.

    Returns
    -------
    OpenChain
        With ``dof = 4``; the gripper point of the text is ``point=(0, 0, p)``.

    Raises
    ------
    ValueError
        If `s0` is not a positive number.

    Notes
    -----
    The closed forms (2-75) are `example_2_25_pose`; both are derived in
    :ref:`deriv-open-chains`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._chain import example_2_25_manipulator
    >>> arm = example_2_25_manipulator(0.5)
    >>> arm
    OpenChain(RRPR)
    >>> np.round(arm.pose([0.0, np.pi / 2, 0.3, 0.0], point=(0, 0, 0.1)).P, 12) + 0.0
    array([0.4, 0. , 0.5])
    """
    s0 = positive_length("s0", s0)
    quarter = np.pi / 2
    return OpenChain([Joint("R", lam=quarter, s=s0), Joint("R", lam=quarter), Joint("P"), Joint("R")])


def example_2_25_pose(phi01, phi12, s2, phi34, s0, p):
    """Closed-form pose of the gripper of example 2-25, eq. (2-75).

    Parameters
    ----------
    phi01, phi12, phi34 : array_like
        The three joint angles, radians.
    s2 : array_like
        The slide S2 = CB.
    s0, p : array_like
        S0 = l_AB, and the gripper point's offset p along z4.

    Returns
    -------
    P, e1, e3 : ndarray, shape (..., 3)
        (x0, y0, z0) of (2-75), the direction cosines (l, m, n) of e1 and (u, v, w) of e3.

    Raises
    ------
    ValueError
        If a value is not finite.

    Notes
    -----
    Generated from :ref:`deriv-open-chains`, where it is proved equal to the product
    M01 M12 M23 M34 and to the textbook's printed results.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._chain import example_2_25_pose
    >>> P, e1, e3 = example_2_25_pose(0.0, np.pi / 2, 0.3, 0.0, 0.5, 0.1)
    >>> np.round(P, 12)
    array([0.4, 0. , 0.5])
    """
    args = [finite_array(n, v) for n, v in zip(("phi01", "phi12", "s2", "phi34", "s0", "p"),
                                               (phi01, phi12, s2, phi34, s0, p))]
    args = np.broadcast_arrays(*args)
    x0, y0, z0, l, m, n, u, v, w = (np.broadcast_to(x, args[0].shape) for x in _gen.example_2_25_pose(*args))
    return np.stack([x0, y0, z0], -1), np.stack([l, m, n], -1), np.stack([u, v, w], -1)


def example_2_25_reach(phi12, s2, s0, p):
    """Distance AP from the base origin to the gripper point in example 2-25.

    AP = sqrt(S0^2 + (p + S2)^2 - 2 S0 (p + S2) cos phi12), evaluated in the form
    sqrt((S0 - p - S2)^2 + 4 S0 (p + S2) sin^2(phi12 / 2)), free of cancellation.

    Parameters
    ----------
    phi12 : array_like
        Shoulder angle, radians.
    s2, s0, p : array_like
        The slide S2, the height S0 = l_AB and the gripper offset p.

    Returns
    -------
    AP : ndarray
        Broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If a value is not finite.

    Notes
    -----
    The gripper point lies on the sphere of radius p + S2 about the shoulder B = (0, 0, S0);
    AP is the distance from A, as the textbook states it. See :ref:`deriv-open-chains`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._chain import example_2_25_reach
    >>> float(example_2_25_reach(np.pi / 2, 0.2, 0.3, 0.2))
    0.5
    """
    phi12, s2, s0, p = (finite_array(n, v) for n, v in zip(("phi12", "s2", "s0", "p"), (phi12, s2, s0, p)))
    # the squares inside the root see lengths divided by a power of two (mech._scaling)
    unit = length_scale_array(s2, s0, p)
    return np.asarray(_gen.example_2_25_reach(phi12, s2 / unit, s0 / unit, p / unit) * unit)[()]
