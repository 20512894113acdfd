"""The relative-motion (graphical) method by computation: polygons and images, F38-F43.

The textbook solves a linkage by drawing vector equations such as
``v_C = v_B + v_CB`` to scale. Here every vector of such an equation is computed from a
solved `Linkage` (``mech.planar.kinematics._linkage``), so the polygon can be drawn exactly, its
closure checked, and every length read off for a chosen scale.

Two kinds of equation cover the chapter:

- two points of one rigid link (F38-F40): ``v_P = v_Q + v_PQ`` with ``v_PQ = omega x QP``,
  ``a_P = a_Q + a_PQ^n + a_PQ^t`` with ``a_PQ^n = -omega^2 QP`` and ``a_PQ^t = alpha x QP``;
- two coincident points of a sliding pair (F41-F43): ``v_P3 = v_P2 + v_P3P2`` along the
  guide, ``a_P3 = a_P2 + a_P3P2^r + a_P3P2^k`` with the Coriolis term
  ``a^k = 2 omega x v_P3P2``.

Names of vectors follow the textbook (``"v_CB"``, ``"a_CB^n"``, ``"a_B3B2^k"``); names of
polygon vertices are lower case (``"p"`` the pole, ``"b"``, ``"c"``, ``"n_cb"`` the tip of
``a_CB^n``, ``"k_b3"`` the tip of a Coriolis term); figures add the primes of the
acceleration polygon.
"""

from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from mech._errors import InputTypeError
from mech._validate import finite_result, instance, known_name, planar_points, positive_length

__all__ = [
    "Term",
    "Equation",
    "RelativeMotion",
    "Polygon",
    "Image",
    "relative_motion",
    "coincident_motion",
    "velocity_polygon",
    "acceleration_polygon",
    "velocity_image",
    "acceleration_image",
]

POLE = "p"


@dataclass(frozen=True)
class Term:
    """One vector of a relative-motion equation, drawn from vertex ``tail`` to ``head``.

    ``name`` is the textbook's name (``"v_CB"``, ``"a_C^n"``, ``"a_B3B2^k"``), ``vector``
    the value (complex, in the units of the solution).
    """

    name: str
    tail: str
    head: str
    vector: np.ndarray


@dataclass(frozen=True)
class Equation:
    """A vector equation ``sum(lhs) = sum(rhs)``; both chains start at the pole."""

    lhs: tuple
    rhs: tuple

    @property
    def residual(self):
        """``sum(lhs) - sum(rhs)``: zero (to rounding) when the polygon closes."""
        return sum(t.vector for t in self.lhs) - sum(t.vector for t in self.rhs)

    @property
    def text(self):
        """The equation as the textbook writes it, e.g. ``"v_C = v_B + v_CB"``."""
        return " + ".join(t.name for t in self.lhs) + " = " + " + ".join(t.name for t in self.rhs)

    @property
    def terms(self):
        """Every term, left side first."""
        return self.lhs + self.rhs


@dataclass(frozen=True)
class RelativeMotion:
    """The velocity and the acceleration equation of one point (see `relative_motion`)."""

    velocity: Equation
    acceleration: Equation


@dataclass(frozen=True)
class Polygon:
    """A velocity or acceleration polygon: the pole, labelled vertices and their equations.

    ``vertices`` maps each vertex label to its vector from the pole (``"p"`` maps to 0);
    ``equations`` are the vector equations drawn, in order.
    """

    kind: str
    vertices: MappingProxyType
    equations: tuple

    @property
    def closure(self):
        """Largest ``|residual|`` over the equations (zero to rounding for a solved linkage)."""
        return max(float(np.max(np.abs(eq.residual))) for eq in self.equations)

    @property
    def terms(self):
        """Every term of every equation, by name (the first occurrence of a name wins)."""
        out = {}
        for eq in self.equations:
            for t in eq.terms:
                out.setdefault(t.name, t)
        return MappingProxyType(out)

    def segment(self, tail, head):
        """The vector from vertex ``tail`` to vertex ``head``."""
        known_name("tail", tail, tuple(self.vertices))
        known_name("head", head, tuple(self.vertices))
        return self.vertices[head] - self.vertices[tail]

    def lengths(self, mu):
        """Drawing length of every term at the scale ``mu`` (vector units per unit length).

        For the textbook's ``mu_v = 0.05 (m/s)/mm`` with velocities in mm/s, pass
        ``mu = 50.0``: a velocity of 1000 mm/s is then drawn 20 mm long.
        """
        mu = positive_length("mu", mu)
        with np.errstate(over="ignore"):
            out = {name: np.abs(t.vector) / mu for name, t in self.terms.items()}
        for name, value in out.items():
            finite_result(value, f"the length of {name!r}", mu=mu)
        return MappingProxyType(out)


@dataclass(frozen=True)
class Image:
    """The velocity or acceleration image of points of one rigid link.

    ``names``, ``figure`` (positions) and ``tips`` (velocities or accelerations, the image
    vertices measured from the pole) are in the same order; ``factor`` is the complex
    number with ``tips[k] - tips[0] = factor * (figure[k] - figure[0])``: ``1j*omega`` for
    velocities, ``1j*alpha - omega**2`` for accelerations.
    """

    kind: str
    names: tuple
    figure: np.ndarray
    tips: np.ndarray
    factor: np.ndarray

    @property
    def scale(self):
        """Size of the image over the size of the link, ``|omega|`` or ``sqrt(alpha^2 + omega^4)``."""
        return np.abs(self.factor)

    @property
    def rotation(self):
        """Angle (radians, counter-clockwise) from the link figure to its image."""
        return np.angle(self.factor)


def _pick(sol, mapping, what, name, arg):
    try:
        return np.asarray(getattr(sol, mapping)[name])
    except (KeyError, TypeError):
        known = ", ".join(sorted(getattr(sol, mapping))) or "none"
        raise ValueError(f"Expected `{arg}` to be a {what} of the solution ({known}), got {name!r}") from None
    except AttributeError:
        raise ValueError(f"Expected `sol` to be a LinkageSolution solved with order=2, got {sol!r}") from None


def _kin(sol, name, arg):
    """Position, velocity and acceleration of a named point (the argument ``arg``)."""
    return (_pick(sol, "points", "point", name, arg), _pick(sol, "velocities", "point", name, arg),
            _pick(sol, "accelerations", "point", name, arg))


def _rates(sol, link, arg):
    return _pick(sol, "omegas", "link", link, arg), _pick(sol, "alphas", "link", link, arg)


def _low(name):
    return name.lower()


def _fixed(v, a):
    return bool(np.all(v == 0) and np.all(a == 0))


def _about(sol, point, pos, pivot, link, tip, link_arg="link"):
    """Chains for the motion of ``point`` (at ``pos``) on ``link`` about ``pivot``."""
    Q, vQ, aQ = _kin(sol, pivot, "pivot")
    w, al = _rates(sol, link, link_arg)
    r = pos - Q
    fixed = _fixed(vQ, aQ)
    rel = point if fixed else point + pivot
    n_tip = "n_" + _low(rel)
    vt = Term(f"v_{rel}", POLE if fixed else _low(pivot), tip, 1j * w * r)
    an = Term(f"a_{rel}^n", POLE if fixed else _low(pivot), n_tip, -(w * w) * r)
    at = Term(f"a_{rel}^t", n_tip, tip, 1j * al * r)
    if fixed:
        return (vt,), (an, at)
    return (Term(f"v_{pivot}", POLE, _low(pivot), vQ), vt), (Term(f"a_{pivot}", POLE, _low(pivot), aQ), an, at)


def relative_motion(sol, point, *, base, link, pivot=None, pivot_link=None):
    """The equations ``v_P = v_Q + v_PQ`` and ``a_P = a_Q + a_PQ^n + a_PQ^t`` on one link.

    Two points P (``point``) and Q (``base``) of one rigid ``link`` (F38-F40): the right
    side is ``v_Q + omega x QP`` and ``a_Q - omega^2 QP + alpha x QP``. The left side is
    the solver's ``v_P`` and ``a_P``, or, with ``pivot``, the motion of P about the point
    ``pivot`` of ``pivot_link`` (default ``link``), split into normal and tangential parts
    like the textbook's ``a_C^n + a_C^t`` (a pivot at rest with zero acceleration, such as
    a ground pivot, is left out of the chain and names the terms ``v_C``, ``a_C^n``).

    Parameters
    ----------
    sol : LinkageSolution
        Solved with ``order=2``; its arrays may have any shape.
    point, base, pivot : str
        Point names of the solution.
    link, pivot_link : str
        Link names of the solution.

    Returns
    -------
    RelativeMotion
        ``velocity`` and ``acceleration`` `Equation`; the residual of each is the polygon's
        failure to close.

    Raises
    ------
    ValueError
        For a name that the solution does not know.

    Notes
    -----
    The vectors come from the solver's rates (derivation page :ref:`deriv-assur-groups`);
    nothing is measured from a drawing. Book page: :ref:`book-relative-motion`.

    Examples
    --------
    Example 2-10's coupler: ``v_C = v_B + v_CB`` with ``v_C = 0``:

    >>> from mech.planar.kinematics._polygons import example_2_10
    >>> m = relative_motion(example_2_10(), "C", base="B", link="2", pivot="D", pivot_link="3")
    >>> m.velocity.text
    'v_C = v_B + v_CB'
    >>> [round(float(abs(t.vector)), 6) for t in m.velocity.terms]
    [0.0, 1000.0, 1000.0]
    >>> m.acceleration.text
    'a_C^n + a_C^t = a_B + a_CB^n + a_CB^t'
    """
    P, vP, aP = _kin(sol, point, "point")
    Q, vQ, aQ = _kin(sol, base, "base")
    w, al = _rates(sol, link, "link")
    r = P - Q
    tip, bq, n_tip = _low(point), _low(base), "n_" + _low(point + base)
    rhs_v = (Term(f"v_{base}", POLE, bq, vQ), Term(f"v_{point}{base}", bq, tip, 1j * w * r))
    rhs_a = (Term(f"a_{base}", POLE, bq, aQ), Term(f"a_{point}{base}^n", bq, n_tip, -(w * w) * r),
             Term(f"a_{point}{base}^t", n_tip, tip, 1j * al * r))
    if pivot is None:
        lhs_v, lhs_a = (Term(f"v_{point}", POLE, tip, vP),), (Term(f"a_{point}", POLE, tip, aP),)
    else:
        lhs_v, lhs_a = _about(sol, point, P, pivot, link if pivot_link is None else pivot_link, tip,
                              "link" if pivot_link is None else "pivot_link")
    return RelativeMotion(Equation(lhs_v, rhs_v), Equation(lhs_a, rhs_a))


def coincident_motion(sol, point, *, carrier, link, pivot):
    """The equations of two coincident points of a sliding pair, with the Coriolis term.

    ``point`` is the pin whose motion the solver knows, as a point of ``carrier`` (P2);
    P3 is the point of the other link ``link`` of the sliding pair that coincides with it
    at this instant (F41-F43)::

        v_P3 = v_P2 + v_P3P2                      (v_P3P2 along the guide)
        a_P3 = a_P2 + a_P3P2^r + a_P3P2^k         (a^k = 2 omega x v_P3P2)

    The left side is split about ``pivot`` (a point of ``link``) into normal and
    tangential parts, as in the textbook's ``a_3B^n + a_3B^t``. The relative terms are
    the solver's sliding rates; the left side is rigid-body motion of ``link``, so the
    residual is a real check. A straight guide has no relative normal term.

    Parameters
    ----------
    sol : LinkageSolution
        Solved with ``order=2``, with a sliding pair between ``carrier`` and ``link``.
    point, pivot : str
        Point names.
    carrier, link : str
        The two links of the sliding pair.

    Returns
    -------
    RelativeMotion
        Points on links are named point + link (``"B3"``, ``"B2"``).

    Raises
    ------
    ValueError
        For an unknown name, or links that do not form a sliding pair.

    Notes
    -----
    The Coriolis term is zero when the guide does not turn (omega = 0, as in the sine
    mechanism, or at an instant like example 2-10's) or when nothing slides. Book page:
    :ref:`book-relative-motion`.

    Examples
    --------
    Example 2-9 with unit crank and speed: ``alpha_3 = -2 omega_1**2``:

    >>> from mech.planar.kinematics._polygons import example_2_9
    >>> m = coincident_motion(example_2_9(), "B", carrier="2", link="3", pivot="C")
    >>> m.acceleration.text
    'a_B3^n + a_B3^t = a_B2 + a_B3B2^k + a_B3B2^r'
    >>> round(float(abs(m.acceleration.rhs[1].vector)), 12)   # 2 sqrt(2) omega^2 l
    2.828427124746
    """
    P, vP, aP = _kin(sol, point, "point")
    slides = getattr(sol, "slides", {})
    if not all(isinstance(x, str) for x in (carrier, link)):      # link names are strings
        raise InputTypeError(f"Expected `carrier` and `link` to be link names, got {(carrier, link)!r}")
    if (carrier, link) in slides:
        sl, sign = slides[(carrier, link)], -1.0
    elif (link, carrier) in slides:
        sl, sign = slides[(link, carrier)], 1.0
    else:
        pairs = ", ".join(map(str, sorted(slides))) or "none"
        raise ValueError(f"Expected (`carrier`, `link`) to be a sliding pair of the solution ({pairs}), "
                         f"got {(carrier, link)!r}")
    if sl.a is None:
        raise ValueError(f"Expected a LinkageSolution solved with order=2, got {sol!r}")
    d = np.asarray(sl.direction)
    p3, p2, rel = point + link, point + carrier, point + link + point + carrier
    t3, t2, k = _low(p3), _low(p2), "k_" + _low(p3)
    rhs_v = (Term(f"v_{p2}", POLE, t2, vP), Term(f"v_{rel}", t2, t3, sign * np.asarray(sl.v) * d))
    rhs_a = (Term(f"a_{p2}", POLE, t2, aP), Term(f"a_{rel}^k", t2, k, sign * np.asarray(sl.coriolis)),
             Term(f"a_{rel}^r", k, t3, sign * np.asarray(sl.a) * d))
    lhs_v, lhs_a = _about(sol, p3, P, pivot, link, t3)
    return RelativeMotion(Equation(lhs_v, rhs_v), Equation(lhs_a, rhs_a))


def _polygon(kind, equations):
    vertices = {POLE: 0j}
    for eq in equations:
        for chain in (eq.rhs, eq.lhs):
            at = 0j
            for t in chain:
                at = at + t.vector
                vertices.setdefault(t.head, at)
    return Polygon(kind, MappingProxyType(vertices), tuple(equations))


def _motions(motions):
    if isinstance(motions, (str, bytes)) or not hasattr(motions, "__iter__"):
        raise InputTypeError(f"Expected `motions` to be a sequence of RelativeMotion, got {motions!r}")
    motions = list(motions)
    for k, m in enumerate(motions):
        instance(f"motions[{k}]", m, RelativeMotion)
    return motions


def velocity_polygon(motions):
    """The velocity polygon of a sequence of `RelativeMotion` (pole ``"p"``).

    Vertex positions are the vectors from the pole; a vertex shared by two equations
    (``b`` in ``v_C = v_B + v_CB`` and ``v_E = v_B + v_EB``) keeps its first position, and
    `Polygon.closure` measures how far any equation is from closing.

    Examples
    --------
    >>> from mech.planar.kinematics._polygons import example_2_10
    >>> sol = example_2_10()
    >>> vp = velocity_polygon([relative_motion(sol, "C", base="B", link="2", pivot="D", pivot_link="3")])
    >>> sorted(vp.vertices), vp.closure < 1e-9
    (['b', 'c', 'p'], True)
    """
    return _polygon("velocity", [m.velocity for m in _motions(motions)])


def acceleration_polygon(motions):
    """The acceleration polygon of a sequence of `RelativeMotion` (pole ``"p"``, drawn p').

    Examples
    --------
    >>> from mech.planar.kinematics._polygons import example_2_10
    >>> sol = example_2_10()
    >>> ap = acceleration_polygon([relative_motion(sol, "C", base="B", link="2", pivot="D", pivot_link="3")])
    >>> complex(ap.vertices["c"]).real.__round__(6)
    -12500.0
    """
    return _polygon("acceleration", [m.acceleration for m in _motions(motions)])


def _image(kind, sol, link, base, points):
    Q, vQ, aQ = _kin(sol, base, "base")
    w, al = _rates(sol, link, "link")
    if isinstance(points, (str, bytes)) or not hasattr(points, "__iter__"):
        raise InputTypeError(f"Expected `points` to be point names or a mapping of names to points, got {points!r}")
    names = tuple(points) if not hasattr(points, "keys") else tuple(points.keys())
    if not names:
        raise ValueError(f"Expected `points` to name at least one point, got {points!r}")
    if hasattr(points, "keys"):
        figure = np.stack([planar_points(f"points[{n!r}]", points[n]) * np.ones_like(Q) for n in names])
    else:
        figure = np.stack([_pick(sol, "points", "point", n, "points") for n in names])
    factor = 1j * w if kind == "velocity" else 1j * al - w * w
    start = vQ if kind == "velocity" else aQ
    tips = start + factor * (figure - Q)
    return Image(kind, names, figure, tips, np.asarray(factor))


def velocity_image(sol, link, base, points):
    """The velocity image of points of one link: ``v_k = v_Q + omega x QZ_k`` (F38).

    The image is the figure of the link turned by 90 degrees in the sense of ``omega`` and
    scaled by ``|omega|``, with the same order of vertices; the pole is the image of every
    point at rest.

    Parameters
    ----------
    sol : LinkageSolution
        Solved with ``order=2``.
    link : str
        The rigid link.
    base : str
        A point of ``link`` whose motion the solution knows.
    points : sequence of str, or mapping of str to complex
        Points of the solution on ``link``, or named positions (such as a point on the
        extension of a link) rigidly attached to it.

    Returns
    -------
    Image
        ``factor = 1j * omega``: ``rotation`` is +-pi/2, ``scale`` is ``|omega|``.

    Examples
    --------
    >>> from mech.planar.kinematics._polygons import example_2_10
    >>> img = velocity_image(example_2_10(), "2", "B", ["B", "C"])
    >>> float(img.scale), round(float(img.rotation), 12)
    (2.5, 1.570796326795)
    """
    return _image("velocity", sol, link, base, points)


def acceleration_image(sol, link, base, points):
    """The acceleration image of points of one link: ``a_k = a_Q + (alpha i - omega^2) QZ_k``.

    The image is the figure turned by ``180 deg - phi`` in the sense of ``alpha``, with
    ``tan(phi) = |alpha| / omega^2`` (F40), and scaled by ``sqrt(alpha^2 + omega^4)``;
    the order of the vertices is kept. Parameters as in `velocity_image`.

    Examples
    --------
    Example 2-10's link 3 (omega_3 = 0, alpha_3 = 62.5): its image is the link turned by
    90 degrees, so C, D, E stay on one line with ``c'd' = d'e'``:

    >>> from mech.planar.kinematics._polygons import example_2_10
    >>> img = acceleration_image(example_2_10(), "3", "D", ["C", "D", "E"])
    >>> [complex(t).real.__round__(6) for t in img.tips]
    [-12500.0, 0.0, 12500.0]
    """
    return _image("acceleration", sol, link, base, points)


def example_2_10():
    """Example 2-10's six-bar solved at the instant of Fig. 2-51 (a helper for doctests).

    A = 0, B = 100, C = 500, D = 500 - 200j, E = 500 - 400j, F = D + 200 sqrt(3); crank 1
    at 10 rad/s clockwise; links 2 = BC, 3 = CDE, 4 = block at E, 5 = guide EF. Millimetres.
    """
    from mech.planar.kinematics._linkage import Linkage

    F = 500 + 200 * np.sqrt(3) - 200j
    lk = (Linkage({"A": 0, "D": 500 - 200j, "F": F})
          .crank("1", pivot="A", tip="B", length=100)
          .rrr(("2", "3"), pins=("B", "D"), joint="C", lengths=(400, 200), branch=1)
          .point("E", link="3", at=-200)
          .rpr(("5", "4"), pins=("F", "E"), branch=1))
    return lk.solve(0.0, order=2, omega=-10.0, strict=True)


def example_2_9(length=1.0, omega=1.0):
    """Example 2-9's guide-bar solved at the instant of Fig. 2-50 (a helper for doctests).

    A = 0, C = sqrt(2) l, crank AB = l at 45 degrees turning clockwise at ``omega``; block 2
    pinned at B slides in the slot of guide 3, perpendicular to AC, at l/sqrt(2) from C.
    """
    from mech.planar.kinematics._linkage import Linkage

    l = float(length)
    lk = (Linkage({"A": 0, "C": np.sqrt(2) * l})
          .crank("1", pivot="A", tip="B", length=l)
          .rpr(("3", "2"), pins=("C", "B"), offset=l / np.sqrt(2), branch=1))
    return lk.solve(np.pi / 4, order=2, omega=-float(omega), strict=True)
