"""Side-angle laws of single-loop spherical polygons (the monograph's chapter 5).

A single-loop spherical linkage of n links is a spherical polygon: joint axes
``u_1 .. u_n`` (unit vectors through the centre), link k from ``u_k`` to ``u_{k+1}`` with
twist (arc) ``alpha_k``, and the joint angle ``theta_k`` at ``u_k``: the angle from the
normal of link k-1 to the normal of link k, counter-clockwise about ``u_k`` seen from
outside (the turning angle at the vertex; the interior angle is ``pi - theta_k``).

Arrays follow that numbering: ``arcs[..., k-1]`` is ``alpha_k`` and ``angles[..., k-1]`` is
``theta_k``; axis numbers ``j``, ``k`` in the laws are 1-based, as in the derivation.

A cut ``(j, k)`` splits the loop at ``u_j`` and ``u_k`` into a forward and a backward open
chain; comparing the two expressions of ``u_k`` gives the sine law, the sine-cosine law
and the cosine law of the cut, eq. (6) of :ref:`deriv-spherical-polygon-laws`
(``derivations/spherical/polygon_laws.md``). Every formula is generated there
(``mech/_generated/spherical_polygons.py``).
"""

from collections.abc import Mapping
from itertools import permutations
from types import MappingProxyType

import numpy as np

from mech._generated import spherical_polygons as _gen
from mech._validate import arc_array as _arcs, common_shape, finite_array, integer, option
from mech.spherical._coordinates import _norm

__all__ = [
    "chain_components",
    "open_chain_axes",
    "SphericalPolygon",
    "close_polygon",
    "sine_law",
    "sine_cosine_law",
    "cosine_law",
    "polygon_relations",
    "PolygonRelations",
    "law_count",
]

_CHAINS = {m: getattr(_gen, f"spherical_chain_{m}") for m in range(1, 7)}
_FAMILIES = ("sine", "sine-cosine", "cosine")


def _polygon_arrays(arcs, angles):
    arcs, angles = _arcs("arcs", arcs), finite_array("angles", angles)
    if arcs.ndim == 0 or not 3 <= arcs.shape[-1] <= 7:
        raise ValueError(f"Expected `arcs` with 3 to 7 entries on its last axis, got shape {arcs.shape}")
    if angles.ndim == 0 or angles.shape[-1] != arcs.shape[-1]:
        raise ValueError(f"Expected `angles` with {arcs.shape[-1]} entries on its last axis, as `arcs` "
                         f"{arcs.shape}, got shape {angles.shape}")
    shape = common_shape(arcs=arcs, angles=angles)
    return np.broadcast_to(arcs, shape), np.broadcast_to(angles, shape)


def _axis_number(name, value, n):
    return integer(name, value, minimum=1, maximum=n)


def _chain(arcs, angles):
    """(X, Y, Z) of the chain with twists ``arcs[..., :]``, angles ``angles[..., :]``."""
    m = arcs.shape[-1]
    X, Y, Z = _CHAINS[m](*np.moveaxis(arcs, -1, 0), *np.moveaxis(angles, -1, 0))
    shape = np.broadcast_shapes(arcs.shape[:-1], angles.shape[:-1])
    return tuple(np.broadcast_to(np.asarray(c, dtype=float), shape) for c in (X, Y, Z))


def chain_components(arcs, angles):
    """End axis of a spherical open chain in its start frame: the recursive (X, Y, Z), eq. (2).

    A chain of m links runs through the axes ``u_1 .. u_{m+1}``; link i has twist
    ``arcs[..., i-1]`` and ``angles[..., i-2]`` is the joint angle at the interior axis
    ``u_i`` (i = 2..m). The start frame has z along ``u_1`` and x along the normal
    ``u_1 x u_2 / sin(alpha_1)`` of the first link. Then ``Z = cos(rho)`` and
    ``(X, Y) = sin(rho) (sin(chi), -cos(chi))``, with ``rho`` the arc from ``u_1`` to
    ``u_{m+1}`` and ``chi`` the angle at ``u_1`` from the first link to that arc.

    Parameters
    ----------
    arcs : array_like, shape (..., m)
        Link twists in (0, pi), radians, 1 <= m <= 6.
    angles : array_like, shape (..., m - 1)
        Joint angles at the interior axes, radians.

    Returns
    -------
    X, Y, Z : ndarray, shape (...)
        Components of the unit vector ``u_{m+1}`` in the start frame.

    Raises
    ------
    ValueError
        If an arc is outside (0, pi), an angle is not finite, or the shapes do not fit.

    Notes
    -----
    The recursion (3) of :ref:`deriv-spherical-polygon-laws` adds one link at the start of
    the chain; it is the rotation part of the H-D product (2-73) with zero offsets.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._polygons import chain_components
    >>> X, Y, Z = chain_components([np.pi / 2, np.pi / 2], [np.pi / 2])
    >>> np.round([X, Y, Z], 12) + 0.0
    array([1., 0., 0.])
    """
    arcs, angles = _arcs("arcs", arcs), finite_array("angles", angles)
    if arcs.ndim == 0 or not 1 <= arcs.shape[-1] <= 6:
        raise ValueError(f"Expected `arcs` with 1 to 6 entries on its last axis, got shape {np.shape(arcs)}")
    m = arcs.shape[-1]
    if m > 1 and (angles.ndim == 0 or angles.shape[-1] != m - 1):
        raise ValueError(f"Expected `angles` with {m - 1} entries on its last axis, one fewer than `arcs` "
                         f"{arcs.shape}, got shape {angles.shape}")
    if m == 1:
        angles = np.zeros(arcs.shape[:-1] + (0,))
    return _chain(arcs, angles)


def open_chain_axes(arcs, angles, *, frame=None):
    """Every joint axis of a spherical open chain placed anywhere on the sphere, eq. (1).

    By default the chain starts at the north pole ``u_1 = (0, 0, 1)`` with its first link
    heading along +x, so ``u_2 = (sin alpha_1, 0, cos alpha_1)``: the placement of the
    spherical four-bar's ground link A -> D. A proper rotation `frame` R moves the whole
    chain: ``u_i = R @ u_i(default)``. With the fixed local frame of the sphere, a chain
    starting at ``to_xyz(lon, lat)`` whose first link has the inclination ``heading`` uses
    the R built by ``ground_frame(lon, lat, heading)``.

    Parameters
    ----------
    arcs : array_like, shape (..., m)
        Link twists in (0, pi), radians, m >= 1.
    angles : array_like, shape (..., m - 1)
        Turning angles at the interior axes ``u_2 .. u_m``: from link i-1 continued beyond
        ``u_i`` to link i, counter-clockwise seen from outside, radians.
    frame : array_like, shape (..., 3, 3), optional
        Proper rotation placing the chain; None for the identity.

    Returns
    -------
    axes : ndarray, shape (..., m + 1, 3)
        Unit vectors ``u_1 .. u_{m+1}``.

    Raises
    ------
    ValueError
        If an arc is outside (0, pi), a value is not finite, or the shapes do not fit.

    Notes
    -----
    The frames follow ``F_{i+1} = F_i R_z(theta_i) R_x(alpha_i)``, eq. (1) of
    :ref:`deriv-spherical-polygon-laws`, from the start frame ``R @ R_z(pi/2)`` (x along the
    first link's normal). As the arcs shrink, ``u_i`` approaches the north pole along the
    planar polygon with sides ``alpha_i`` and turning angles ``theta_i``.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._polygons import open_chain_axes
    >>> u = open_chain_axes([np.pi / 2, np.pi / 2, np.pi / 2], [np.pi / 2, np.pi / 2])
    >>> np.round(u, 12) + 0.0
    array([[0., 0., 1.],
           [1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    arcs, angles = _arcs("arcs", arcs), finite_array("angles", angles)
    if arcs.ndim == 0 or arcs.shape[-1] < 1:
        raise ValueError(f"Expected `arcs` with at least 1 entry on its last axis, got shape {arcs.shape}")
    m = arcs.shape[-1]
    if m > 1 and (angles.ndim == 0 or angles.shape[-1] != m - 1):
        raise ValueError(f"Expected `angles` with {m - 1} entries on its last axis, one fewer than `arcs` "
                         f"{arcs.shape}, got shape {angles.shape}")
    if m == 1:
        angles = np.zeros(arcs.shape[:-1] + (0,))
    batch = np.broadcast_shapes(arcs.shape[:-1], angles.shape[:-1])
    arcs = np.broadcast_to(arcs, batch + (m,))
    turns = np.concatenate([np.zeros(batch + (1,)), np.broadcast_to(angles, batch + (m - 1,))], axis=-1)
    R = np.eye(3) if frame is None else finite_array("frame", frame)
    if R.shape[-2:] != (3, 3):
        raise ValueError(f"Expected `frame` of shape (..., 3, 3), got shape {R.shape}")
    start = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])   # R_z(pi/2)
    M = R @ start
    shape = np.broadcast_shapes(M.shape[:-2], arcs.shape[:-1], turns.shape[:-1])
    M = np.broadcast_to(M, shape + (3, 3))
    out = [M[..., :, 2]]
    for i in range(m):
        entries = _gen.chain_link_rotation(turns[..., i], arcs[..., i])
        T = np.stack([np.broadcast_to(np.asarray(e, dtype=float), shape) for e in entries], axis=-1)
        M = M @ T.reshape(shape + (3, 3))
        out.append(M[..., :, 2])
    return np.stack(out, axis=-2)


class SphericalPolygon:
    """A closed spherical polygon: its axes, twists and joint angles (immutable).

    Attributes
    ----------
    axes : ndarray, shape (..., n, 3)
        Unit joint axes ``u_1 .. u_n``.
    arcs : ndarray, shape (..., n)
        Twists ``alpha_k``, the arc from ``u_k`` to ``u_{k+1}``.
    angles : ndarray, shape (..., n)
        Joint angles ``theta_k`` at ``u_k``, in (-pi, pi].
    """

    __slots__ = ("axes", "arcs", "angles")

    def __init__(self, axes, arcs, angles):
        for name, value in (("axes", axes), ("arcs", arcs), ("angles", angles)):
            value = np.array(value, dtype=float)
            value.flags.writeable = False
            object.__setattr__(self, name, value)

    def __setattr__(self, name, value):
        raise AttributeError("SphericalPolygon is immutable")

    @property
    def n(self):
        """Number of links (and axes)."""
        return self.arcs.shape[-1]

    def relations(self):
        """Residuals of every side-angle law: ``polygon_relations(self.arcs, self.angles)``."""
        return polygon_relations(self.arcs, self.angles)

    def __repr__(self):
        return f"SphericalPolygon(n={self.n}, shape={self.arcs.shape[:-1]})"


def close_polygon(axes):
    """The closed spherical polygon through the given joint axes.

    Parameters
    ----------
    axes : array_like, shape (..., n, 3)
        Nonzero vectors along the joint axes ``u_1 .. u_n`` (normalised here); consecutive
        axes (and ``u_n``, ``u_1``) must be neither parallel nor antiparallel.

    Returns
    -------
    SphericalPolygon
        With ``arcs[..., k-1] = atan2(|u_k x u_{k+1}|, u_k . u_{k+1})`` and
        ``angles[..., k-1]`` the signed angle from the normal of link k-1 to the normal of
        link k about ``u_k``.

    Raises
    ------
    ValueError
        If an axis is zero or not finite, or two consecutive axes are (anti)parallel.

    Notes
    -----
    Used to build test polygons for the laws of :ref:`deriv-spherical-polygon-laws`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._polygons import close_polygon
    >>> octant = close_polygon(np.eye(3))
    >>> octant.arcs / (np.pi / 2)          # three quarter circles
    array([1., 1., 1.])
    >>> octant.angles / (np.pi / 2)        # three right turns
    array([1., 1., 1.])
    """
    u = finite_array("axes", axes)
    if u.ndim < 2 or u.shape[-1] != 3 or u.shape[-2] < 3:
        raise ValueError(f"Expected `axes` of shape (..., n, 3) with n >= 3, got shape {u.shape}")
    norm = _norm(u)[..., None]
    if np.any(norm == 0.0):
        raise ValueError("Expected nonzero `axes`, got a zero vector")
    u = u / norm
    nxt = np.roll(u, -1, axis=-2)
    cross = np.cross(u, nxt)
    sine = _norm(cross)
    if np.any(sine == 0.0):
        raise ValueError("Expected consecutive `axes` that are not parallel, got a parallel pair")
    arcs = np.arctan2(sine, np.sum(u * nxt, axis=-1))
    normal = cross / sine[..., None]
    before = np.roll(normal, 1, axis=-2)
    angles = np.arctan2(np.sum(u * np.cross(before, normal), axis=-1), np.sum(before * normal, axis=-1))
    return SphericalPolygon(u, arcs, angles)


def _chain_indices(n, j, k):
    """0-based twist and angle indices of the forward and backward chains of the cut (j, k)."""
    m = (k - j) % n
    fwd = ([(j - 1 + i) % n for i in range(m)], [(j - 1 + i) % n for i in range(1, m)])
    bwd = ([(j - 2 - i) % n for i in range(n - m)], [(j - 1 - i) % n for i in range(1, n - m)])
    return fwd, bwd


def _cut(arcs, angles, j, k):
    n = arcs.shape[-1]
    (ft, fa), (bt, ba) = _chain_indices(n, j, k)
    plus = _chain(arcs[..., ft], angles[..., fa])
    minus = _chain(arcs[..., bt], angles[..., ba])
    return _gen.polygon_cut_laws(*plus, *minus, angles[..., j - 1])


def _law(arcs, angles, j, k, family):
    arcs, angles = _polygon_arrays(arcs, angles)
    n = arcs.shape[-1]
    j, k = _axis_number("j", j, n), _axis_number("k", k, n)
    if j == k:
        raise ValueError(f"Expected `k` different from `j`, got k = j = {j}")
    shape = arcs.shape[:-1]
    return np.broadcast_to(np.asarray(_cut(arcs, angles, j, k)[family], dtype=float), shape)


_LAW_DOC = """{title} of the cut (j, k) of a closed spherical polygon: its residual, eq. (6).

    {meaning}

    Parameters
    ----------
    arcs, angles : array_like, shape (..., n)
        Twists ``alpha_1 .. alpha_n`` in (0, pi) and joint angles ``theta_1 .. theta_n``,
        radians, 3 <= n <= 7.
    j, k : int
        The axes where the loop is cut, 1-based, ``j != k``.

    Returns
    -------
    residual : ndarray, shape (...)
        Left side minus right side; zero (to rounding) on a closed polygon.

    Raises
    ------
    ValueError
        If an arc is outside (0, pi), a value is not finite, or j, k are not valid.

    Notes
    -----
    ``(X, Y, Z)+`` and ``(X, Y, Z)-`` are the chain components (2) of the forward chain
    ``j -> j+1 -> .. -> k`` and the backward chain ``j -> j-1 -> .. -> k``; see
    :ref:`deriv-spherical-polygon-laws`. The law never contains ``theta_k``.{extra}

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._polygons import close_polygon, {name}
    >>> p = close_polygon(np.random.default_rng(1).normal(size=(5, 3)))
    >>> bool(abs({name}(p.arcs, p.angles, 2, 4)) < 1e-14)
    True
"""


def sine_law(arcs, angles, j, k):
    return _law(arcs, angles, j, k, 0)


def sine_cosine_law(arcs, angles, j, k):
    return _law(arcs, angles, j, k, 1)


def cosine_law(arcs, angles, j, k):
    return _law(arcs, angles, j, k, 2)


sine_law.__doc__ = _LAW_DOC.format(
    title="Sine law", name="sine_law", extra="",
    meaning="``X+ = X- cos(theta_j) - Y- sin(theta_j)``; for ``k = j - 1`` (the fundamental form)\n"
            "    ``X_{j -> j-1} = sin(alpha_{j-1}) sin(theta_j)``.")
sine_cosine_law.__doc__ = _LAW_DOC.format(
    title="Sine-cosine law", name="sine_cosine_law", extra="",
    meaning="``Y+ = -(X- sin(theta_j) + Y- cos(theta_j))``; for ``k = j - 1`` (the fundamental\n"
            "    form) ``Y_{j -> j-1} = sin(alpha_{j-1}) cos(theta_j)``.")
cosine_law.__doc__ = _LAW_DOC.format(
    title="Cosine law", name="cosine_law",
    extra=" Nor ``theta_j``: the cosine law is the\n    relation free of the two joint angles at the cut, and (j, k), (k, j) give the same\n"
          "    law (residuals of opposite sign).",
    meaning="``Z+ = Z-``, both equal to ``u_j . u_k``; for ``k = j - 1`` (the fundamental form)\n"
            "    ``Z_{j -> j-1} = cos(alpha_{j-1})``.")


class PolygonRelations(Mapping):
    """Residuals of every side-angle law of a polygon, keyed by law name (read-only mapping).

    Keys are ``"sine(j,k)"`` and ``"sine-cosine(j,k)"`` for every ordered cut, and
    ``"cosine(j,k)"`` for ``j < k``; values are arrays of the polygons' batch shape.
    """

    __slots__ = ("n", "_residuals")

    def __init__(self, n, residuals):
        object.__setattr__(self, "n", n)
        object.__setattr__(self, "_residuals", MappingProxyType(dict(residuals)))

    def __setattr__(self, name, value):
        raise AttributeError("PolygonRelations is immutable")

    def __getitem__(self, key):
        return self._residuals[key]

    def __iter__(self):
        return iter(self._residuals)

    def __len__(self):
        return len(self._residuals)

    def family(self, name):
        """Stack of the residuals of one family ("sine", "sine-cosine", "cosine"), laws last."""
        option("name", name, _FAMILIES)
        return np.stack([v for key, v in self._residuals.items() if key.split("(")[0] == name], axis=-1)

    def worst(self):
        """Largest absolute residual over all laws, per polygon."""
        return np.max(np.abs(np.stack(list(self._residuals.values()), axis=-1)), axis=-1)

    def __repr__(self):
        return f"PolygonRelations(n={self.n}, laws={len(self)})"


def polygon_relations(arcs, angles):
    """Residuals of every sine, sine-cosine and cosine law of closed spherical polygons.

    Parameters
    ----------
    arcs, angles : array_like, shape (..., n)
        Twists ``alpha_1 .. alpha_n`` in (0, pi) and joint angles ``theta_1 .. theta_n``,
        radians, 3 <= n <= 7 (the loops of the monograph's chapter 5).

    Returns
    -------
    PolygonRelations
        A read-only mapping from law names (``"sine(1,3)"``, ``"sine-cosine(1,3)"``,
        ``"cosine(1,3)"``) to residual arrays of shape (...); ``law_count(n)`` laws.

    Raises
    ------
    ValueError
        If an arc is outside (0, pi), an angle is not finite, or the shapes do not fit.

    Notes
    -----
    Every cut (j, k) gives the three laws (6) of :ref:`deriv-spherical-polygon-laws`; the
    cuts (j, j-1) give the fundamental forms (7), the others the supplementary ones. The
    cosine law of (k, j) equals that of (j, k) and is listed once.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._polygons import close_polygon, polygon_relations
    >>> p = close_polygon(np.random.default_rng(0).normal(size=(100, 4, 3)))
    >>> rel = polygon_relations(p.arcs, p.angles)
    >>> len(rel), bool(rel.worst().max() < 1e-14)
    (30, True)
    """
    arcs, angles = _polygon_arrays(arcs, angles)
    n = arcs.shape[-1]
    residuals = {}
    for j, k in permutations(range(1, n + 1), 2):
        sine, sine_cosine, cosine = _cut(arcs, angles, j, k)
        residuals[f"sine({j},{k})"] = sine
        residuals[f"sine-cosine({j},{k})"] = sine_cosine
        if j < k:
            residuals[f"cosine({j},{k})"] = cosine
    shape = arcs.shape[:-1]
    return PolygonRelations(n, {key: np.broadcast_to(np.asarray(v, dtype=float), shape)
                                for key, v in residuals.items()})


def law_count(n):
    """Number of laws of an n-loop by family: ``n(n-1)`` sine, as many sine-cosine, ``n(n-1)/2`` cosine.

    Examples
    --------
    >>> from mech.spherical._polygons import law_count
    >>> law_count(4)
    {'sine': 12, 'sine-cosine': 12, 'cosine': 6, 'total': 30}
    """
    n = integer("n", n, minimum=3)
    pairs = n * (n - 1)
    counts = {"sine": pairs, "sine-cosine": pairs, "cosine": pairs // 2}
    counts["total"] = sum(counts.values())
    return counts
