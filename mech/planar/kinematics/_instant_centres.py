"""Instant centres of planar linkages by the three-centre (Kennedy) theorem, F32-F37.

Every centre is held in homogeneous coordinates ``(X, Y, W)``: a finite point ``z`` is
``(Re z, Im z, 1)`` and a point at infinity in the direction ``u`` is ``(Re u, Im u, 0)``.
A line through two points is their cross product and two lines meet at the cross product
of the lines, so centres at infinity (sliding pairs, translating links) need no special
case anywhere.
"""

import numbers
from dataclasses import dataclass
from itertools import combinations

import numpy as np

from mech._errors import InputTypeError, UnknownKeyError
from mech._validate import finite_array, instance, integer, known_name, planar_points

__all__ = [
    "Centre",
    "InstantCentres",
    "LinkVelocities",
    "centre_count",
    "higher_pair",
    "instant_centres",
    "omega_ratio",
    "prismatic",
    "revolute",
    "centre_velocities",
]

# A centre farther than 1/_INFINITE_RTOL times the linkage's size counts as at infinity.
_INFINITE_RTOL = 1e-12
# Lines (unit homogeneous vectors) closer than this to coincidence leave a centre undefined.
_COINCIDENT_TOL = 64 * np.finfo(float).eps


@dataclass(frozen=True)
class _Direct:
    kind: str          # "revolute", "prismatic" or "line"
    first: object      # point (complex array), or sliding direction
    second: object = None


def revolute(point):
    """A direct centre at a finite point: a revolute pair or a rolling contact (F33).

    Parameters
    ----------
    point : complex or array_like of complex
        The joint centre (or contact point), ``x + 1j*y``.
    """
    return _Direct("revolute", _complex("point", point))


def prismatic(direction):
    """A sliding pair: the centre is at infinity perpendicular to `direction` (F33).

    Parameters
    ----------
    direction : complex or array_like of complex
        The sliding direction (any non-zero length).
    """
    return _Direct("prismatic", 1j * _direction("direction", direction))


def higher_pair(contact, normal):
    """A higher pair that slides: the centre lies on the common normal at the contact (F33).

    Parameters
    ----------
    contact : complex or array_like of complex
        The contact point.
    normal : complex or array_like of complex
        Direction of the common normal there (any non-zero length, either sense).
    """
    return _Direct("line", _complex("contact", contact), _direction("normal", normal))


def _complex(name, value):
    return planar_points(name, value)


def _direction(name, value):
    arr = _complex(name, value)
    if np.any(arr == 0):
        raise ValueError(f"Expected a non-zero `{name}`, got 0j")
    return arr / np.abs(arr)


def centre_count(n):
    """Number of instant centres of an `n`-link mechanism, frame included (F32, §2.2 II).

    ``N = n (n - 1) / 2``: one centre for each pair of links.

    >>> centre_count(4), centre_count(6)
    (6, 15)
    """
    n = integer("n", n, minimum=2)
    return n * (n - 1) // 2


@dataclass(frozen=True)
class Centre:
    """One instant centre P_ij (all fields broadcast over the poses).

    Attributes
    ----------
    pair : tuple
        The two link labels ``(i, j)`` in the order of `InstantCentres.links`.
    homogeneous : ndarray, shape (..., 3)
        ``(X, Y, W)``; ``W = 1`` for finite direct centres.
    point : ndarray of complex
        ``(X + iY) / W``; NaN where the centre is at infinity or undefined.
    direction : ndarray of complex
        Unit direction of a centre at infinity; NaN where it is finite.
    at_infinity, defined : ndarray of bool
        Where the centre is at infinity; where the lines that place it are distinct.
    source : str
        ``"revolute"``, ``"prismatic"``, ``"kennedy"`` or ``"kennedy+line"``.
    """

    pair: tuple
    homogeneous: np.ndarray
    point: np.ndarray
    direction: np.ndarray
    at_infinity: np.ndarray
    defined: np.ndarray
    source: str


@dataclass(frozen=True)
class ConstructionStep:
    """How a centre was found: P_ij lies on the line P_ik P_jk for every k in `via`.

    ``line`` is True when the centre's own higher-pair normal was one of the lines;
    ``round`` counts the sweeps of Kennedy's theorem (0 for direct centres).
    """

    pair: tuple
    round: int
    via: tuple
    line: bool


class InstantCentres:
    """All n(n-1)/2 instant centres of a linkage; returned by `instant_centres`.

    Index with a pair of link labels, in either order: ``centres[1, 3]`` is a `Centre`.

    Attributes
    ----------
    links : tuple
        The link labels.
    construction : tuple of ConstructionStep
        Every centre in the order it was found (direct ones first, round 0).
    """

    def __init__(self, links, centres, construction):
        object.__setattr__(self, "links", links)
        object.__setattr__(self, "_centres", centres)
        object.__setattr__(self, "construction", construction)

    def __setattr__(self, name, value):
        raise AttributeError("InstantCentres is immutable")

    def _key(self, pair):
        try:
            i, j = pair
        except (TypeError, ValueError):
            raise UnknownKeyError(f"Expected a pair of link labels, got {pair!r}") from None
        order = {label: k for k, label in enumerate(self.links)}
        if i not in order or j not in order or i == j:
            raise UnknownKeyError(f"Expected two different links among {self.links}, got {pair!r}")
        return (i, j) if order[i] < order[j] else (j, i)

    def __getitem__(self, pair):
        return self._centres[self._key(pair)]

    def __len__(self):
        return len(self._centres)

    def __iter__(self):
        return iter(self._centres)

    def pairs(self):
        """All pairs, in the order of `links`."""
        return tuple(self._centres)

    def __repr__(self):
        return f"InstantCentres(links={self.links}, count={len(self)})"


def _normalise(v):
    norm = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, norm, out=np.zeros_like(v), where=norm > 0)


def _homogeneous_point(z):
    return np.stack([z.real, z.imag, np.ones(z.shape)], axis=-1)


def _homogeneous_direction(u):
    return np.stack([u.real, u.imag, np.zeros(u.shape)], axis=-1)


def _meet(lines):
    """The common point of unit lines, shape (..., m, 3) with m >= 2, by the SVD."""
    if lines.shape[-2] == 2:
        point = np.cross(lines[..., 0, :], lines[..., 1, :])
        defined = np.linalg.norm(point, axis=-1) > _COINCIDENT_TOL
        return _normalise(point), defined
    _, s, vh = np.linalg.svd(lines)
    defined = s[..., -2] > _COINCIDENT_TOL * s[..., 0]
    return vh[..., -1, :], defined


def _labels(links):
    if (isinstance(links, (bool, np.bool_, str, bytes, numbers.Number)) or not hasattr(links, "__iter__")
            or (isinstance(links, np.ndarray) and links.ndim == 0) or isinstance(links, (dict, set, frozenset))):
        return tuple(range(1, integer("links", links, minimum=2, maximum=10**4) + 1))
    labels = tuple(links)
    for label in labels:
        # a label must be hashable and equal to itself (NaN is not), and be no flag or array
        try:
            hash(label)
            usable = label == label and not isinstance(label, (bool, np.bool_))
        except (TypeError, ValueError):
            usable = False
        if not usable:
            raise InputTypeError(f"Expected `links` to be a count or link labels, got {label!r} in {links!r}")
    if len(labels) < 2 or len(set(labels)) != len(labels):
        raise ValueError(f"Expected `links` to be at least two distinct link labels, got {links!r}")
    return labels


def instant_centres(links, direct, *, undefined="raise"):
    """All instant centres of a planar linkage by the three-centre theorem (F32, F33).

    Centres of directly connected links are given; every other P_ij is placed by Kennedy's
    theorem: P_ij, P_ik, P_jk are collinear for every third link k, so P_ij is where two
    (or more) lines P_ik P_jk meet, or one such line meets the common normal of a higher
    pair between i and j. Sweeps repeat until nothing new is found.

    Parameters
    ----------
    links : int or sequence of hashable
        Number of links n (labelled 1..n, frame included) or their labels.
    direct : mapping
        ``{(i, j): spec}`` with `spec` a complex point (revolute pair or rolling contact,
        or `revolute`), `prismatic` (sliding direction) or `higher_pair` (contact and
        common normal). Arrays broadcast: one centre per pose.
    undefined : {"raise", "nan"}, optional
        What to do where the lines that should place a centre coincide (a degenerate
        pose, e.g. all joints of a four-bar on one line): raise a ValueError naming the
        centre, the pose and the centres that fall on one line (default), or return NaN
        there with the mask ``defined`` False.

    Returns
    -------
    InstantCentres
        ``n (n - 1) / 2`` centres by pair, with ``construction`` in the order found.

    Raises
    ------
    ValueError
        For unknown labels, repeated pairs, non-finite points or zero directions, and
        when Kennedy's theorem cannot place every centre, naming those left over; with
        ``undefined="raise"``, where a centre's lines coincide at some pose.

    Notes
    -----
    Homogeneous coordinates make centres at infinity ordinary points (derivation
    :ref:`deriv-instant-centres`). A centre is `defined` where its lines are distinct.
    Where they coincide the positions alone do not fix the centre (it depends on the
    velocities, which this construction does not see), so it is reported, not guessed.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.kinematics._instant_centres import instant_centres
    >>> B, C = 3 + 4j, 10 + 6j              # a four-bar with A = 0, D = 8
    >>> ic = instant_centres(4, {(1, 4): 0j, (1, 2): B, (2, 3): C, (3, 4): 8 + 0j})
    >>> len(ic), [step.pair for step in ic.construction[4:]]
    (6, [(1, 3), (2, 4)])
    >>> complex(np.round(ic[2, 4].point, 9))  # where the lines AB and DC meet
    (14.4+19.2j)
    """
    if not (isinstance(undefined, str) and undefined in ("raise", "nan")):
        raise ValueError(f"Expected `undefined` to be 'raise' or 'nan', got {undefined!r}")
    labels = _labels(links)
    index = {label: k for k, label in enumerate(labels)}
    known, lines, steps, sources = {}, {}, [], {}
    if not hasattr(direct, "items"):
        raise InputTypeError(f"Expected `direct` to be a mapping of link pairs to centres, got {direct!r}")
    for raw_pair, spec in dict(direct).items():
        try:
            i, j = raw_pair
        except (TypeError, ValueError):
            raise ValueError(f"Expected a pair of link labels as key, got {raw_pair!r}") from None
        if i not in index or j not in index or i == j:
            raise ValueError(f"Expected `direct` keys to be pairs of two different links among `links` {labels}, got {raw_pair!r}")
        pair = (i, j) if index[i] < index[j] else (j, i)
        if pair in known or pair in lines:
            raise ValueError(f"Expected each pair once in `direct`, got {pair!r} twice")
        if not isinstance(spec, _Direct):
            spec = _Direct("revolute", _complex(f"direct[{raw_pair!r}]", spec))
        if spec.kind == "line":
            lines[pair] = spec
            continue
        known[pair] = spec
        sources[pair] = spec.kind
    shape = np.broadcast_shapes(*(np.shape(s.first) for s in (*known.values(), *lines.values())))
    finite = [np.abs(s.first) for s in (*known.values(), *lines.values()) if s.kind != "prismatic"]
    scale = max([1.0] + [float(np.max(f)) for f in finite if f.size])
    hom = {}
    for pair, spec in known.items():
        z = np.broadcast_to(spec.first, shape)
        hom[pair] = _homogeneous_point(z / scale) if spec.kind == "revolute" else _homogeneous_direction(z)
        steps.append(ConstructionStep(pair, 0, (), False))
    normal_lines = {
        pair: _normalise(np.cross(_homogeneous_point(np.broadcast_to(s.first, shape) / scale),
                                  _homogeneous_direction(np.broadcast_to(s.second, shape))))
        for pair, s in lines.items()
    }
    defined = {pair: np.ones(shape, dtype=bool) for pair in hom}
    all_pairs = [(labels[p], labels[q]) for p, q in combinations(range(len(labels)), 2)]
    sweep = 0
    while True:
        sweep += 1
        found = {}
        for i, j in all_pairs:
            if (i, j) in hom:
                continue
            via, rows = [], []
            for k in labels:
                ik = (i, k) if index[i] < index[k] else (k, i)
                jk = (j, k) if index[j] < index[k] else (k, j)
                if k not in (i, j) and ik in hom and jk in hom:
                    via.append(k)
                    rows.append(_normalise(np.cross(hom[ik], hom[jk])))
            if (i, j) in normal_lines:
                rows.append(normal_lines[(i, j)])
            if len(rows) >= 2:
                point, ok = _meet(np.stack(rows, axis=-2))
                ok &= np.all([defined[(i, k) if index[i] < index[k] else (k, i)]
                              & defined[(j, k) if index[j] < index[k] else (k, j)] for k in via], axis=0)
                found[(i, j)] = (point, ok)
                steps.append(ConstructionStep((i, j), sweep, tuple(via), (i, j) in normal_lines))
                sources[(i, j)] = "kennedy+line" if (i, j) in normal_lines else "kennedy"
        if not found:
            break
        for pair, (point, ok) in found.items():
            hom[pair], defined[pair] = point, ok
    missing = [p for p in all_pairs if p not in hom]
    if missing:
        names = ", ".join(f"P_{i}{j}" if len(f"{i}{j}") == 2 else f"P_({i},{j})" for i, j in missing)
        raise ValueError(
            f"Expected the three-centre theorem to place every centre, but {names} "
            f"{'is' if len(missing) == 1 else 'are'} left: fewer than two lines through known "
            "centres meet there. The linkage may have more than one degree of freedom, or be a "
            "class III linkage that needs more than Kennedy's theorem (solve the velocity "
            "equations instead)."
        )
    if undefined == "raise":
        _raise_undefined(steps, defined, shape, index)
    return InstantCentres(labels, {p: _centre(p, hom[p], defined[p], scale, sources[p]) for p in all_pairs},
                          tuple(steps))


def _name(i, j):
    return f"P_{i}{j}" if len(f"{i}{j}") == 2 else f"P_({i},{j})"


def _raise_undefined(steps, defined, shape, index):
    """Raise a ValueError for the first centre, in construction order, left undefined."""
    for step in steps:
        bad = ~np.asarray(defined[step.pair])
        if not np.any(bad):
            continue
        pose = tuple(int(k) for k in np.argwhere(np.broadcast_to(bad, shape))[0])
        where = f"pose {pose}" if pose else "this pose"
        i, j = step.pair

        def pair(x, y):
            return _name(x, y) if index[x] < index[y] else _name(y, x)

        lines = [f"the line through {pair(i, k)} and {pair(j, k)}" for k in step.via]
        if step.line:
            lines.append(f"the common normal of the higher pair {_name(i, j)}")
        raise ValueError(
            f"Expected the three-centre theorem to place {_name(i, j)}, but at {where} "
            f"{' and '.join(lines)} coincide or are undefined (centres that coincide, or "
            "all on one line, e.g. all joints of a four-bar in line): the positions alone "
            "do not fix it. Pass undefined='nan' for NaN there with the mask `defined`."
        )


def _centre(pair, h, defined, scale, source):
    X, Y, W = h[..., 0], h[..., 1], h[..., 2]
    xy = X + 1j * Y
    at_inf = np.abs(W) <= _INFINITE_RTOL * np.abs(xy)
    safe_w = np.where(at_inf | ~defined, 1.0, W)
    point = np.where(at_inf | ~defined, np.nan + 0j, scale * xy / safe_w)
    mag = np.where(at_inf & defined, np.abs(xy), 1.0)
    direction = np.where(at_inf & defined, xy / mag, np.nan + 0j)
    user = np.stack([scale * X, scale * Y, W], axis=-1)
    user = np.where(defined[..., None], user, np.nan)
    return Centre(pair, user, point[()], direction[()], at_inf[()], defined[()], source)


def _rate_factor(centres, i, j, frame):
    """Real factor s with (omega_i / W_i) = s (omega_j / W_j), from P_ij, P_if, P_jf."""
    R = centres[i, j].homogeneous
    Ai = centres[i, frame].homogeneous
    Aj = centres[j, frame].homogeneous
    r, ai, aj = (h[..., 0] + 1j * h[..., 1] for h in (R, Ai, Aj))
    u = r * Aj[..., 2] - aj * R[..., 2]          # W_R W_j (P_ij - P_jf)
    v = r * Ai[..., 2] - ai * R[..., 2]          # W_R W_i (P_ij - P_if)
    with np.errstate(divide="ignore", invalid="ignore"):
        return (u * v.conj()).real / (v * v.conj()).real


def omega_ratio(centres, i, j, frame):
    """Angular velocity ratio omega_i / omega_j from three collinear centres (F34).

    At P_ij links i and j have the same velocity, so with signed positions along the line
    of P_if, P_jf and P_ij: ``omega_i / omega_j = (P_ij - P_jf) / (P_ij - P_if)``.

    Parameters
    ----------
    centres : InstantCentres
        From `instant_centres`.
    i, j, frame : hashable
        Two moving links and the link the angular velocities are measured against.

    Returns
    -------
    ndarray or float
        Positive when both turn the same way (P_ij outside the segment P_if P_jf),
        negative when P_ij lies between them; 0 where link i translates, 1 where i and j
        translate relative to each other, infinite where link j translates.

    Notes
    -----
    Evaluated in homogeneous coordinates, so centres at infinity need no special case
    (derivation :ref:`deriv-instant-centres`).

    Examples
    --------
    >>> from mech.planar.kinematics._instant_centres import instant_centres, omega_ratio
    >>> ic = instant_centres(4, {(1, 4): 0j, (1, 2): 3 + 4j, (2, 3): 10 + 6j, (3, 4): 8 + 0j})
    >>> round(float(omega_ratio(ic, 3, 1, 4)), 12)     # P13 = -11: (-11 - 0) / (-11 - 8)
    0.578947368421
    """
    instance("centres", centres, InstantCentres)
    for name, label in (("i", i), ("j", j), ("frame", frame)):
        known_name(name, label, centres.links)
    if frame in (i, j):
        if frame == j:
            raise ValueError(f"Expected `j` to differ from `frame` (the frame does not turn), got {j!r}")
        return np.zeros(np.shape(centres[j, frame].point))[()]
    if i == j:
        return np.ones(np.shape(centres[i, frame].point))[()]
    Wi = centres[i, frame].homogeneous[..., 2]
    Wj = centres[j, frame].homogeneous[..., 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        return (_rate_factor(centres, i, j, frame) * Wi / Wj)[()]


@dataclass(frozen=True)
class LinkVelocities:
    """Angular velocities of every link and velocities of their points (`centre_velocities`).

    Attributes
    ----------
    omega : dict
        Link label -> angular velocity relative to the frame (0 for a translating link).
    """

    omega: dict
    _rates: dict
    _centres: InstantCentres
    _frame: object

    def point_velocity(self, link, z):
        """Velocity of the point `z` (complex, the frame's coordinates) on `link`.

        ``v = i omega (z - P_link,frame)``; for a translating link (absolute centre at
        infinity) the same formula in homogeneous coordinates gives the common velocity.
        """
        z = planar_points("z", z)
        known_name("link", link, tuple(self._rates))
        if link == self._frame:
            return np.zeros(np.broadcast_shapes(z.shape, np.shape(self.omega[link])), complex)[()]
        h = self._centres[link, self._frame].homogeneous
        return (1j * self._rates[link] * (z * h[..., 2] - (h[..., 0] + 1j * h[..., 1])))[()]


def centre_velocities(centres, frame, driver, omega):
    """Angular velocities of all links from the input link's, by the centres (F34-F37).

    Parameters
    ----------
    centres : InstantCentres
        From `instant_centres`.
    frame, driver : hashable
        The fixed link and the input link (it must turn about a finite centre).
    omega : float or array_like
        Angular velocity of `driver`, counter-clockwise positive.

    Returns
    -------
    LinkVelocities
        ``omega[link]`` for every link and ``point_velocity(link, z)``.

    Raises
    ------
    ValueError
        If `driver` is the frame or translates (its absolute centre is at infinity).

    Notes
    -----
    Each link k is related to the driver through P_kd (derivation
    :ref:`deriv-instant-centres`); a translating link gets omega = 0 and its velocity
    from the same relation.

    Examples
    --------
    >>> from mech.planar.kinematics._instant_centres import instant_centres, prismatic, centre_velocities
    >>> ic = instant_centres(4, {(1, 4): 0j, (1, 2): 3 + 4j, (2, 3): 8 + 0j, (3, 4): prismatic(1)})
    >>> motion = centre_velocities(ic, frame=4, driver=1, omega=2.0)
    >>> round(float(motion.omega[2]), 12), round(complex(motion.point_velocity(3, 0j)).real, 12)
    (-1.2, -12.8)
    """
    instance("centres", centres, InstantCentres)
    known_name("frame", frame, centres.links)
    known_name("driver", driver, centres.links)
    if driver == frame:
        raise ValueError(f"Expected a `driver` other than the frame, got {driver!r}")
    omega = finite_array("omega", omega)
    Wd = centres[driver, frame].homogeneous[..., 2]
    if np.any(Wd == 0) or not np.all(centres[driver, frame].defined):
        raise ValueError(f"Expected the driver {driver!r} to turn about a finite centre, "
                         f"got its centre P_{driver}{frame} at infinity")
    base = omega / Wd
    rates, omegas = {}, {}
    for link in centres.links:
        if link == frame:
            rates[link] = np.zeros_like(base)
            omegas[link] = rates[link][()]
            continue
        rates[link] = base if link == driver else base * _rate_factor(centres, link, driver, frame)
        omegas[link] = (rates[link] * centres[link, frame].homogeneous[..., 2])[()]
    return LinkVelocities(omegas, rates, centres, frame)
