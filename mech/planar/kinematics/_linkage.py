"""Any planar linkage of revolute and sliding pairs: drivers, then class II Assur groups.

The formulas come from ``derivations/planar/assur_groups.md`` through
``mech._generated.assur_groups``; this module only orders the steps, carries the state
(points, link directions, rates) from one group to the next, and reports failures.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from types import MappingProxyType

import numpy as np

from mech._errors import AssemblyError, InputTypeError
from mech._scaling import DEAD_POINT_RTOL
from mech._generated import assur_groups as _g
from mech.planar.kinematics import _linkage_blocks, _linkage_modes
from mech._validate import (
    bool_flag, branch_sign, finite_array, integer, known_name, MAX_COUNT, nonnegative_int, planar_point, positive_length, real_number, common_shape)

__all__ = ["Linkage", "LinkageSolution", "Guide", "Slide", "AssemblyInterval"]

GROUND = "ground"


def _for(arg):
    return "" if arg is None else f" for `{arg}`"


def _two(name, value):
    """Unpack a pair of names (links, pins, guides) given as a tuple or list."""
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise InputTypeError(f"Expected `{name}` to be a pair, got {value!r}")
    return tuple(value)


def _looks_numeric(text):
    """True for a string such as "10" that would name a driver but reads as a number."""
    try:
        float(text)
    except ValueError:
        return False
    return True


@dataclass(frozen=True)
class Guide:
    """A straight guide fixed in a link: through a point of it, at an angle to the link.

    ``through`` is a point name, or local coordinates (complex) in the link's frame;
    ``angle`` is measured from the link's x axis (for the ground: from +x).
    """

    link: str
    through: object = 0j
    angle: float = 0.0

    def __post_init__(self):
        if not isinstance(self.through, str) or _looks_numeric(self.through):
            object.__setattr__(self, "through", planar_point("through", self.through))
        object.__setattr__(self, "angle", real_number("angle", self.angle))


@dataclass(frozen=True)
class Slide:
    """Relative motion in one sliding pair: the moving link along the guiding link.

    ``s`` is the position along the guide, ``v`` and ``a`` its first and second time
    derivatives (the relative sliding velocity and acceleration, along ``direction``),
    ``coriolis`` the Coriolis acceleration 2 omega x v_rel (complex), where
    omega is the angular velocity of the guiding link.
    """

    s: np.ndarray
    direction: np.ndarray
    v: np.ndarray = None
    a: np.ndarray = None
    coriolis: np.ndarray = None


@dataclass(frozen=True)
class AssemblyInterval:
    """A closed interval of one driver's input where the linkage assembles."""

    start: float
    end: float


@dataclass(frozen=True)
class _Step:
    kind: str
    label: str
    links: tuple
    data: tuple          # (key, value) pairs, so the step stays hashable and immutable

    def get(self, key):
        return dict(self.data)[key]


def _re_im(z):
    return np.real(z), np.imag(z)


class Linkage:
    """A planar linkage built as drivers followed by class II Assur groups.

    Build it with the chained methods below (each returns a new, immutable ``Linkage``),
    then call :meth:`solve` on arrays of input values. Links are named by strings; the
    frame is ``"ground"``. Points are complex numbers. Every link has a frame: an origin
    point and a direction, set by the step that creates it (listed with each method), and
    ``point(name, link=..., at=...)`` attaches a point by its local coordinates there.

    Parameters
    ----------
    ground : mapping of str to complex, optional
        Named fixed points.
    rtol : float, optional
        Where a group's distance comes within ``rtol`` times the linkage's size (the sum of
        its lengths, offsets and the distances of its ground and guide points from the
        origin; a + b + c + d for a four-bar) of the value at which its two modes meet, the
        modes count as meeting there (a change point), as in `FourBar`.

    Notes
    -----
    Derivation: ``derivations/planar/assur_groups.md`` (eqs. 2-11 to 2-18). Each group with
    two assembly modes (RRR, RRP, RPR) has a ``branch`` (the textbook's M) with a geometric
    meaning, and a solution never jumps from one mode to the other.

    *Change points.* Where the two modes of a group meet and part again (its radicand
    touches zero: a parallelogram four-bar at theta = 0 and pi, a slider-crank with
    a + ``|e|`` = b, pins that pass through each other), the motion continues smoothly onto the
    other mode, as `FourBar` does: a parallelogram stays a parallelogram. For a linkage
    driven by one crank the rule is local: the mode at input angle theta is ``branch``
    times -1 for each change point in (0, theta] (for theta < 0, in (theta, 0]), so
    ``branch`` names the mode just after theta = 0 and every input is solved on its own,
    whatever the order of the array. The change points are found once per linkage by
    sampling the crank over the period of each group's pins (2048 samples per turn; two
    change points closer than a sample are missed) and bisecting to rounding. Within four
    samples of a change point, where the loop equations lose digits (rates are 0/0 at the
    point itself), every result is interpolated across it from 16 solutions of the same
    mode further away, so the meeting pose itself is solved, rates included; there
    positions keep about 13 digits, velocities 10 and accelerations 7 or more. Linkages
    with several drivers, or driven by a slider or an actuator, keep each group in the mode
    ``branch`` throughout; where their modes meet, the rates are 0/0 and the pose counts as
    not assembled.

    *Scale.* Each solve works in a power-of-two unit near the longest length (ground
    points, link lengths, guide points, offsets), so any finite lengths from 1e-300 to
    1e300 give the same angles and `valid`, with positions and linear rates in proportion.
    A pose counts as not assembled where a result is not finite (for instance a rate beyond
    the floating-point range).

    Examples
    --------
    The four-bar of example 2-1 as a crank and an RRR group:

    >>> lk = (Linkage({"A": 0, "D": 35})
    ...       .crank("crank", pivot="A", tip="B", length=10)
    ...       .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(40, 30)))
    >>> sol = lk.solve([0.0, 1.0], order=1)
    >>> abs(sol.points["C"] - 35).round(6).tolist()
    [30.0, 30.0]
    """

    def __init__(self, ground=None, *, rtol=1e-12):
        self._rtol = positive_length("rtol", rtol)
        self._steps = ()
        self._points = {}        # name -> link that first carries it
        self._links = {GROUND: None}
        self._guides = {}
        self._drivers = ()
        if ground is not None and not hasattr(ground, "items"):
            raise InputTypeError(f"Expected `ground` to be a mapping of point names to points, got {ground!r}")
        for name, z in dict(ground or {}).items():
            self._add_point(name, GROUND)
            z = planar_point(f"ground[{name!r}]", z)
            self._steps += (_Step("ground", name, (GROUND,), (("at", z),)),)

    # ------------------------------------------------------------------ building
    def _copy(self):
        new = object.__new__(Linkage)
        new._steps = self._steps
        new._points = dict(self._points)
        new._links = dict(self._links)
        new._guides = dict(self._guides)
        new._drivers = self._drivers
        new._rtol = self._rtol
        return new

    def _add_point(self, name, link, arg=None):
        where = _for(arg)
        if not isinstance(name, str) or not name:
            raise ValueError(f"Expected a point name (a non-empty str){where}, got {name!r}")
        if name in self._points:
            raise ValueError(f"Expected a new point name{where}, got {name!r}, which is already defined")
        self._points[name] = link

    def _add_link(self, name, arg=None):
        where = _for(arg)
        if not isinstance(name, str) or not name:
            raise ValueError(f"Expected a link name (a non-empty str){where}, got {name!r}")
        if name in self._links:
            raise ValueError(f"Expected a new link name{where}, got {name!r}, which is already defined")
        self._links[name] = True

    def _need_point(self, name, arg=None):
        if not isinstance(name, str) or name not in self._points:
            known = ", ".join(sorted(self._points)) or "none"
            raise ValueError(f"Expected a known point{_for(arg)}, got {name!r} (known points: {known})")

    def _need_link(self, name, arg=None):
        if not isinstance(name, str) or name not in self._links:
            known = ", ".join(sorted(self._links))
            raise ValueError(f"Expected a known link{_for(arg)}, got {name!r} (known links: {known})")

    def _need_guide(self, guide, arg="guide"):
        if not isinstance(guide, Guide):
            raise InputTypeError(f"Expected `{arg}` to be a Guide(link, through, angle), got {guide!r}")
        self._need_link(guide.link, f"{arg}.link")
        if isinstance(guide.through, str):
            self._need_point(guide.through)
        else:
            complex(guide.through)
        if not math.isfinite(float(guide.angle)):
            raise ValueError(f"Expected a finite guide angle, got {guide.angle!r}")
        return guide

    def _push(self, kind, label, links, **data):
        new = self
        new._steps = new._steps + (_Step(kind, label, tuple(links), tuple(data.items())),)
        return new

    def ground(self, name, at):
        """Add a fixed point ``name`` at ``at`` (complex)."""
        new = self._copy()
        new._add_point(name, GROUND, "name")
        return new._push("ground", name, (GROUND,), at=planar_point("at", at))

    def point(self, name, *, link, at):
        """Attach a point to ``link`` at local coordinates ``at`` (complex) in its frame."""
        new = self._copy()
        new._need_link(link, "link")
        if link == GROUND:
            return new.ground(name, at)
        new._add_point(name, link, "name")
        return new._push("point", name, (link,), at=planar_point("at", at))

    def crank(self, link, *, pivot, tip, length, driver=None):
        """A crank: ``link`` turns about the known point ``pivot`` through the input angle.

        The input is the absolute angle of ``pivot -> tip`` from +x (counter-clockwise);
        the link's frame has its origin at ``pivot`` and its x axis along ``pivot -> tip``.
        """
        new = self._copy()
        new._need_point(pivot, "pivot")
        r = positive_length(f"length of {link}", length)
        new._add_link(link, "link")
        new._add_point(tip, link, "tip")
        name = link if driver is None else driver
        new._drivers = new._drivers + (name,)
        return new._push("crank", f"crank {link}", (link,), pivot=pivot, tip=tip, length=r, driver=name)

    def slider(self, link, *, guide, point, driver=None):
        """A linear driver: ``link`` slides along ``guide`` by the input distance.

        The link's reference point ``point`` is at ``Q + s e`` (Q: the guide's point, e:
        its direction, s: the input); its frame has x along the guide.
        """
        new = self._copy()
        new._need_guide(guide)
        new._add_link(link, "link")
        new._add_point(point, link, "point")
        name = link if driver is None else driver
        new._drivers = new._drivers + (name,)
        return new._push("slider", f"slider {link}", (link, guide.link), guide=guide, point=point, driver=name)

    def rrr(self, links, *, pins, joint, lengths, branch=1):
        """RRR group (eqs. 2-11, 2-12): two links pinned at known ``pins`` and at ``joint``.

        ``branch=+1`` puts ``joint`` to the left of the directed line pins[0] -> pins[1]
        (past change points the mode follows the motion: see `Linkage`). Frames: link 0
        from pins[0] with x towards ``joint``; link 1 from pins[1], likewise. A length
        given as a str is a driver: an actuator whose length is an input.
        """
        new = self._copy()
        l1, l2 = _two("links", links)
        p1, p2 = _two("pins", pins)
        new._need_point(p1, "pins[0]")
        new._need_point(p2, "pins[1]")
        lens = []
        for k, r in enumerate(lengths):
            if isinstance(r, str) and not _looks_numeric(r):
                new._drivers = new._drivers + (r,)
                lens.append(r)
            else:
                lens.append(positive_length(f"lengths[{k}] of the RRR group {l1}-{l2}", r))
        new._add_link(l1, "links[0]")
        new._add_link(l2, "links[1]")
        new._add_point(joint, l1, "joint")
        return new._push("rrr", f"RRR {l1}-{l2}", (l1, l2), pins=(p1, p2), joint=joint,
                         lengths=tuple(lens), branch=branch_sign(branch))

    def rrp(self, links, *, pin, guide, joint, length, branch=1):
        """RRP group (eqs. 2-13 to 2-16): a rod from ``pin`` to a block on ``guide``.

        ``branch=+1`` when ``pin -> joint`` makes an acute angle with the guide direction
        (past change points the mode follows the motion: see `Linkage`). Frames: the rod
        from ``pin`` with x towards ``joint``; the block from ``joint`` with x along the
        guide. The block's sliding pair is ``(links[1], guide.link)``.
        """
        new = self._copy()
        rod, block = _two("links", links)
        new._need_point(pin, "pin")
        new._need_guide(guide)
        r = positive_length(f"length of {rod}", length)
        new._add_link(rod, "links[0]")
        new._add_link(block, "links[1]")
        new._add_point(joint, rod, "joint")
        return new._push("rrp", f"RRP {rod}-{block}", (rod, block), pin=pin, guide=guide, joint=joint,
                         length=r, branch=branch_sign(branch))

    def rpr(self, links, *, pins, offset=0.0, branch=1):
        """RPR group (eqs. 2-17, 2-18): a guide link pinned at pins[0], a block at pins[1].

        The guide line lies at the signed ``offset`` from pins[0] (positive: to the left,
        looking along the guide). ``branch=+1`` when the block is ahead of the foot of
        pins[0] on the guide (past change points the mode follows the motion: see
        `Linkage`). Frames: the guide link from pins[0], x along the guide; the
        block from pins[1], x along the guide. The sliding pair is ``(links[1], links[0])``.
        """
        new = self._copy()
        gl, block = _two("links", links)
        pins = _two("pins", pins)
        for k, p in enumerate(pins):
            new._need_point(p, f"pins[{k}]")
        e = real_number("offset", offset)
        new._add_link(gl, "links[0]")
        new._add_link(block, "links[1]")
        return new._push("rpr", f"RPR {gl}-{block}", (gl, block), pins=tuple(pins), offset=e,
                         branch=branch_sign(branch))

    def prp(self, links, *, guides, joint):
        """PRP group: two blocks on two guides, pinned to each other at ``joint``.

        Frames: each block from ``joint`` with x along its guide. Sliding pairs
        ``(links[0], guides[0].link)`` and ``(links[1], guides[1].link)``.
        """
        new = self._copy()
        b1, b2 = _two("links", links)
        g1, g2 = (new._need_guide(g, f"guides[{k}]") for k, g in enumerate(_two("guides", guides)))
        new._add_link(b1, "links[0]")
        new._add_link(b2, "links[1]")
        new._add_point(joint, b1, "joint")
        return new._push("prp", f"PRP {b1}-{b2}", (b1, b2), guides=(g1, g2), joint=joint)

    def rpp(self, links, *, pin, guide, angle, point, offset=0.0):
        """RPP group: a link pinned at ``pin`` slides along a link that slides on ``guide``.

        The second link slides on ``guide`` and carries an inner guide at ``angle`` to it;
        the first link turns with it, and ``pin`` lies at the signed ``offset`` from the
        inner guide. Frames: the sliding link from its reference ``point`` (on ``guide``,
        where the inner guide crosses it) with x along ``guide``; the pinned link from
        ``pin`` with x along the inner guide. Sliding pairs ``(links[1], guide.link)`` and
        ``(links[0], links[1])``.
        """
        new = self._copy()
        pinned, sliding = _two("links", links)
        new._need_point(pin, "pin")
        new._need_guide(guide)
        gam = real_number("angle", angle)
        offset = real_number("offset", offset)
        if abs(math.sin(gam)) < 1e-12:
            raise ValueError(f"Expected an `angle` not parallel to the guide, got {angle!r}")
        new._add_link(pinned, "links[0]")
        new._add_link(sliding, "links[1]")
        new._add_point(point, sliding, "point")
        return new._push("rpp", f"RPP {pinned}-{sliding}", (pinned, sliding), pin=pin, guide=guide,
                         angle=gam, point=point, offset=float(offset))

    # ------------------------------------------------------------------ reading
    @property
    def drivers(self):
        """Names of the inputs, in the order they were added."""
        return self._drivers

    @property
    def links(self):
        """Names of the links, the ground first."""
        return tuple(self._links)

    @property
    def point_names(self):
        """Names of every point, in the order they were defined."""
        return tuple(self._points)

    @property
    def groups(self):
        """Labels of the drivers and groups, in solving order."""
        return tuple(s.label for s in self._steps if s.kind not in ("ground", "point"))

    def __repr__(self):
        return (f"Linkage({len(self._links) - 1} moving links, {len(self._points)} points, "
                f"drivers={list(self._drivers)})")

    # ------------------------------------------------------------------ solving
    def solve(self, inputs, order=0, omega=1.0, alpha=0.0, strict=False):
        """Positions, and velocities and accelerations up to ``order``, of every point and link.

        Parameters
        ----------
        inputs : array_like or mapping of str to array_like
            The input values (angles in radians for cranks, distances for sliders and
            actuators). A bare array serves a linkage with one driver.
        order : {0, 1, 2}
            Highest time derivative computed. Nothing above it is computed.
        omega, alpha : float, array_like or mapping
            First and second time derivatives of each input (defaults 1 and 0).
        strict : bool
            Raise `mech.AssemblyError` naming the first group that fails and the input
            value, instead of returning NaN with ``valid == False``.

        Returns
        -------
        LinkageSolution

        Raises
        ------
        ValueError
            For non-finite inputs or inputs that do not match the drivers.
        mech.AssemblyError
            With ``strict=True``, naming the first failing group, the input value and,
            for a one-crank linkage, the crank range where it does assemble.

        Notes
        -----
        The modes through change points and the unit of length: see `Linkage`. More than
        16384 poses are solved in blocks of that many, each while its temporaries stay in
        the cache (`mech.planar.kinematics._linkage_blocks`), with the same results.

        Examples
        --------
        >>> lk = (Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)
        ...       .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(20, 10)))
        >>> lk.solve([0.0, 2.0]).valid.tolist()
        [True, False]
        """
        strict = bool_flag("strict", strict)
        order = nonnegative_int("order", order, 2)
        q, w, al = (self._per_driver(x, name) for x, name in
                    ((inputs, "inputs"), (omega, "omega"), (alpha, "alpha")))
        shape = common_shape(**{f"{what}[{d!r}]" if len(x) > 1 else what: v for what, x in
                                (("inputs", q), ("omega", w), ("alpha", al)) for d, v in x.items()})
        unit, steps = self._unit_steps()
        # distance inputs (sliders, actuators) are measured in the same unit as the lengths
        far = self._distance_drivers()
        sq, sw, sal = ({d: x[d] / unit if d in far else x[d] for d in x} for x in (q, w, al))
        crank = self._crank_driver()
        if math.prod(shape) <= _linkage_blocks.BLOCK:
            state, failures = self._solve_all(steps, order, shape, sq, sw, sal, crank, unit)
        else:
            # cache-sized blocks, each solved whole, gathered into outputs allocated once
            state, failures = _linkage_blocks.solve_blocks(self, steps, order, shape, sq, sw, sal, crank, unit)
        if strict and not np.all(state.valid):
            self._raise(failures, q, shape)
        return LinkageSolution(self, order, state, failures)

    def _solve_all(self, steps, order, shape, q, w, al, crank, unit):
        """Solve inputs of `shape` (in the solving unit) at once; return the state and the failures."""
        theta = None if crank is None else np.broadcast_to(q[crank], shape)
        state, failures = self._run(steps, order, shape, q, w, al,
                                    _linkage_modes.modes(self._schedules(), steps, theta))
        if theta is not None:
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                _linkage_modes.bridge(self, steps, self._schedules(), crank, state, theta,
                                      w[crank], al[crank], failures)
        state.drop_unfinished()
        failures = {k: v & ~state.valid for k, v in failures.items()}
        state.rescale(unit)
        state.drop_unfinished()         # a rate beyond the float range at this unit of length
        return state, failures

    def _run(self, steps, order, shape, q, w, al, modes):
        """Solve `steps` (in the unit of `_unit_steps`); return the state and the failures.

        ``modes`` maps each two-mode group to its mode and where its radicand may count as
        zero (`mech.planar.kinematics._linkage_modes.modes`).
        """
        state = _State(order, shape)
        state.modes = modes
        failures = {}
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            for step in steps:
                ok = getattr(self, "_do_" + step.kind)(step, state, q, w, al)
                if ok is not None:
                    ok = np.broadcast_to(ok, shape)
                    first = ~ok & state.valid
                    failures[step.label] = first
                    state.valid = state.valid & ok
        return state, failures

    def _crank_driver(self):
        """The driver's name when the linkage is driven by one crank, else None."""
        cranks = [s.get("driver") for s in self._steps if s.kind == "crank"]
        if len(self._drivers) == 1 and cranks == list(self._drivers):
            return cranks[0]
        return None

    def _schedules(self):
        """The change points of every two-mode group (one-crank linkages only), cached."""
        cached = self.__dict__.get("_schedule_cache")
        if cached is None:
            crank = self._crank_driver()
            cached = {} if crank is None else _linkage_modes.find_schedule(
                self, self._unit_steps()[1], crank, self._rtol * self._size())
            self._schedule_cache = cached
        return cached

    def _distance_drivers(self):
        """Names of the drivers whose input is a distance (sliders and actuators)."""
        out = set()
        for step in self._steps:
            if step.kind == "slider":
                out.add(step.get("driver"))
            elif step.kind == "rrr":
                out.update(x for x in step.get("lengths") if isinstance(x, str))
        return out

    def _unit_steps(self):
        """A power of two ``unit`` near the largest length, and the steps measured in it.

        Solving in this unit makes every intermediate quantity of order one whatever the
        user's unit of length, so lengths anywhere from 1e-300 to 1e300 neither overflow nor
        underflow, and angles do not depend on the unit. A power of two keeps the division
        and the final multiplication exact.
        """
        cached = self.__dict__.get("_unit_cache")
        if cached is not None:
            return cached
        sizes = [0.0]
        for step in self._steps:
            for key, value in step.data:
                if key in _LENGTH_KEYS:
                    sizes.extend(_magnitudes(value))
        largest = max(sizes)
        # 2**(e - 1) <= largest < 2**e; 2**e itself may lie beyond the float range
        unit = math.ldexp(1.0, math.frexp(largest)[1] - 1) if largest > 0 else 1.0
        steps = tuple(_Step(s.kind, s.label, s.links,
                            tuple((k, _in_unit(v, unit) if k in _LENGTH_KEYS else v) for k, v in s.data))
                      for s in self._steps)
        self._unit_cache = (unit, steps)
        return self._unit_cache

    def _size(self):
        """Sum of every length that defines the linkage, in the solving unit.

        Link lengths, offsets, and the distances of ground and guide points from the
        origin: for a four-bar with A = 0 this is a + b + c + d, the size `FourBar` measures
        its change-point tolerance against.
        """
        total = 0.0
        for step in self._unit_steps()[1]:
            for key, value in step.data:
                if key in _LENGTH_KEYS:
                    total += sum(_magnitudes(value, planar=True))
        return total

    def _per_driver(self, value, what):
        if isinstance(value, dict) or hasattr(value, "keys"):
            unknown = set(value) - set(self._drivers)
            if unknown:
                raise ValueError(f"Expected `{what}` keys among the drivers {list(self._drivers)}, "
                                 f"got {sorted(unknown)}")
            missing = set(self._drivers) - set(value)
            if missing and what == "inputs":
                raise ValueError(f"Expected `inputs` for every driver, missing {sorted(missing)}, got {value!r}")
            default = 1.0 if what == "omega" else 0.0
            return {d: finite_array(f"{what}[{d!r}]", value.get(d, default)) for d in self._drivers}
        if len(self._drivers) != 1 and what == "inputs":
            raise ValueError(f"Expected a mapping of inputs for the drivers {list(self._drivers)}, "
                             f"got {type(value).__name__}")
        return {d: finite_array(what, value) for d in self._drivers}

    def _raise(self, failures, q, shape):
        for label, mask in failures.items():
            if np.any(mask):
                idx = np.unravel_index(np.flatnonzero(mask)[0], shape)
                at = ", ".join(f"{d} = {float(np.broadcast_to(v, shape)[idx])!r}" for d, v in q.items())
                raise AssemblyError(f"The group {label!r} cannot be assembled at input {at}{self._range_note()}")

    def _range_note(self):
        """Where a one-crank linkage does assemble, for the error message."""
        cranks = [s for s in self._steps if s.kind == "crank"]
        if len(self._drivers) != 1 or len(cranks) != 1:
            return ""
        found = self.assembly_range()
        if not found:
            return "; it assembles at no crank angle"
        spans = ", ".join(f"[{iv.start:.6g}, {iv.end:.6g}]" for iv in found)
        return f"; it assembles for {self._drivers[0]} in {spans} (radians)"

    # each _do_* computes one step into `state` and returns its validity (or None)
    def _do_ground(self, step, st, q, w, al):
        st.put_point(step.label, step.get("at"), 0.0, 0.0)

    def _do_point(self, step, st, q, w, al):
        link = step.links[0]
        o = st.origin[link]
        d = st.dir[link]
        loc = step.get("at")
        z = _cx(*_g.rigid_body_position(*_re_im(st.P[o]), *_re_im(d), loc.real, loc.imag))
        v = a = None
        if st.order >= 1:
            v = st.rigid_v(o, link, z)
        if st.order >= 2:
            a = st.rigid_a(o, link, z)
        st.put_point(step.label, z, v, a)

    def _do_crank(self, step, st, q, w, al):
        link, pivot, tip, r = step.links[0], step.get("pivot"), step.get("tip"), step.get("length")
        name = step.get("driver")
        d = np.exp(1j * q[name])
        z = _cx(*_g.rigid_body_position(*_re_im(st.P[pivot]), *_re_im(d), r, 0.0))
        st.put_link(link, pivot, d, w[name] if st.order >= 1 else None, al[name] if st.order >= 2 else None)
        v = st.rigid_v(pivot, link, z) if st.order >= 1 else None
        a = st.rigid_a(pivot, link, z) if st.order >= 2 else None
        st.put_point(tip, z, v, a)

    def _guide_state(self, st, guide):
        """Point Q, unit direction e, and the rates of Q and of the guide's link."""
        link = guide.link
        d = st.dir[link]
        if isinstance(guide.through, str):
            Q = st.P[guide.through]
            vQ = st.V.get(guide.through)
            aQ = st.A.get(guide.through)
        else:
            Q = st.P[st.origin[link]] + complex(guide.through) * d if st.origin[link] else complex(guide.through)
            vQ = st.rigid_v(st.origin[link], link, Q) if st.order >= 1 and st.origin[link] else 0.0
            aQ = st.rigid_a(st.origin[link], link, Q) if st.order >= 2 and st.origin[link] else 0.0
        e = d * np.exp(1j * float(guide.angle))
        return Q, e, vQ, aQ, st.W.get(link, 0.0), st.AL.get(link, 0.0)

    def _do_slider(self, step, st, q, w, al):
        link, guide, pt, name = step.links[0], step.get("guide"), step.get("point"), step.get("driver")
        Q, e, vQ, aQ, wK, aK = self._guide_state(st, guide)
        s = q[name]
        z = Q + s * e
        v = a = None
        slide = Slide(s=np.broadcast_to(s, st.shape), direction=np.broadcast_to(e, st.shape))
        if st.order >= 1:
            v = _cx(*_g.slide_velocity(*_re_im(vQ), *_re_im(e), s, w[name], wK))
        if st.order >= 2:
            ax, ay, kx, ky = _g.slide_acceleration(*_re_im(aQ), *_re_im(e), s, w[name], al[name], wK, aK)
            a = ax + 1j * ay
            slide = Slide(slide.s, slide.direction, w[name], al[name], kx + 1j * ky)
        elif st.order >= 1:
            slide = Slide(slide.s, slide.direction, w[name])
        st.put_link(link, pt, e, wK if st.order >= 1 else None, aK if st.order >= 2 else None)
        st.put_point(pt, z, v, a)
        st.put_slide(link, guide.link, slide)

    def _length(self, value, q, w, al, st):
        if isinstance(value, str):
            return q[value], w[value] if st.order >= 1 else 0.0, al[value] if st.order >= 2 else 0.0
        return value, 0.0, 0.0

    def _do_rrr(self, step, st, q, w, al):
        (l1, l2), (p1, p2), joint = step.links, step.get("pins"), step.get("joint")
        (r1, dr1, ddr1), (r2, dr2, ddr2) = (self._length(x, q, w, al, st) for x in step.get("lengths"))
        P1, P2 = st.P[p1], st.P[p2]
        gx, gy = _re_im(P2 - P1)
        heron = _g.rrr_position(gx, gy, r1, r2, 1.0)[2]
        # within DEAD_POINT_RTOL of a dead point (|P2 - P1| = r1 + r2 or |r1 - r2|), and away
        # from a change point, the input is the dead point
        g = np.hypot(gx, gy)
        tol = DEAD_POINT_RTOL * (np.abs(r1) + np.abs(r2) + g)
        dead = (np.abs(np.abs(r1) + np.abs(r2) - g) <= tol) | (np.abs(g - np.abs(r1 - r2)) <= tol)
        heron, dead = _dead_point(st, step, heron, dead)
        rho, ok = _signed_root(st, step, heron)
        ux, uy = _g.rrr_position_root(gx, gy, r1, r2, rho)
        u1 = ux + 1j * uy
        P3 = P1 + u1
        u2 = P3 - P2
        W1 = W2 = A1 = A2 = v3 = a3 = None
        if st.order >= 1:
            W1, W2, vx, vy = _g.rrr_velocity(ux, uy, *_re_im(u2), r1, r2, *_re_im(st.V[p1]),
                                             *_re_im(st.V[p2]), dr1, dr2)
            v3 = vx + 1j * vy
        if st.order >= 2:
            A1, A2, ax, ay = _g.rrr_acceleration(ux, uy, *_re_im(u2), r1, r2, *_re_im(st.A[p1]),
                                                 *_re_im(st.A[p2]), dr1, dr2, ddr1, ddr2, W1, W2)
            a3 = ax + 1j * ay
        if st.order >= 1 and np.any(dead):           # infinite at a dead point: NaN, failed
            W1, W2, v3 = (np.where(dead, np.nan, x) for x in (W1, W2, v3))
            if st.order >= 2:
                A1, A2, a3 = (np.where(dead, np.nan, x) for x in (A1, A2, a3))
        st.put_link(l1, p1, u1 / r1, W1, A1)
        st.put_link(l2, p2, u2 / r2, W2, A2)
        st.put_point(joint, P3, v3, a3)
        return ok & np.isfinite(ux) & np.isfinite(uy)

    def _do_rrp(self, step, st, q, w, al):
        (rod, block), p1, guide, joint, r1 = step.links, step.get("pin"), step.get("guide"), step.get("joint"), step.get("length")
        Q, e, vQ, aQ, wK, aK = self._guide_state(st, guide)
        P1 = st.P[p1]
        (gx, gy), (ex, ey) = _re_im(Q - P1), _re_im(e)
        radicand = _g.rrp_position(gx, gy, ex, ey, r1, 1.0)[3]
        # within DEAD_POINT_RTOL of a dead point (the pin's distance from the guide = r1),
        # and away from a change point, the input is the dead point
        across = ex * gy - ey * gx
        dead = np.abs(np.abs(across) - np.abs(r1)) <= DEAD_POINT_RTOL * (np.abs(r1) + np.hypot(gx, gy))
        radicand, dead = _dead_point(st, step, radicand, dead)
        rho, ok = _signed_root(st, step, radicand)
        s, ux, uy = _g.rrp_position_root(gx, gy, ex, ey, rho)
        u1 = ux + 1j * uy
        P3 = P1 + u1
        W1 = A1 = v3 = a3 = None
        slide = Slide(s=s, direction=np.broadcast_to(e, np.shape(s)))
        if st.order >= 1:
            W1, ds = _g.rrp_velocity(ux, uy, *_re_im(e), r1, s, *_re_im(st.V[p1]), *_re_im(vQ), wK)
            W1, ds = (np.where(dead, np.nan, x) for x in (W1, ds))      # infinite at a dead point
            v3 = _cx(*_g.rigid_body_velocity(*_re_im(st.V[p1]), ux, uy, W1))
            slide = Slide(s, slide.direction, ds)
        if st.order >= 2:
            A1, dds = _g.rrp_acceleration(ux, uy, *_re_im(e), r1, s, *_re_im(st.A[p1]), *_re_im(aQ),
                                          wK, aK, W1, ds)
            a3 = _cx(*_g.rigid_body_acceleration(*_re_im(st.A[p1]), ux, uy, W1, A1))
            _, _, kx, ky = _g.slide_acceleration(*_re_im(aQ), *_re_im(e), s, ds, dds, wK, aK)
            slide = Slide(s, slide.direction, ds, dds, kx + 1j * ky)
        st.put_link(rod, p1, u1 / r1, W1, A1)
        st.put_link(block, joint, e, wK if st.order >= 1 else None, aK if st.order >= 2 else None)
        st.put_point(joint, P3, v3, a3)
        st.put_slide(block, guide.link, slide)
        return ok

    def _do_rpr(self, step, st, q, w, al):
        (gl, block), (p1, p2), e0 = step.links, step.get("pins"), step.get("offset")
        P1, P2 = st.P[p1], st.P[p2]
        gx, gy = _re_im(P2 - P1)
        radicand = _g.rpr_position(gx, gy, e0, 1.0)[3]
        # within DEAD_POINT_RTOL of a dead point (the pins' distance = |offset|), and away
        # from a change point, the input is the dead point
        g = np.hypot(gx, gy)
        dead = np.abs(g - abs(e0)) <= DEAD_POINT_RTOL * (abs(e0) + g)
        radicand, dead = _dead_point(st, step, radicand, dead)
        s, ok = _signed_root(st, step, radicand)
        wx, wy = _g.rpr_position_root(gx, gy, e0, s)
        d = wx + 1j * wy
        W = A = None
        slide = Slide(s=s, direction=d)
        if st.order >= 1:
            W, ds = _g.rpr_velocity(wx, wy, s, e0, *_re_im(st.V[p1]), *_re_im(st.V[p2]))
            W, ds = (np.where(dead, np.nan, x) for x in (W, ds))        # infinite at a dead point
            slide = Slide(s, d, ds)
        if st.order >= 2:
            A, dds, kx, ky = _g.rpr_acceleration(wx, wy, s, e0, *_re_im(st.A[p1]), *_re_im(st.A[p2]), W, ds)
            slide = Slide(s, d, ds, dds, kx + 1j * ky)
        st.put_link(gl, p1, d, W, A)
        st.put_link(block, p2, d, W, A)
        st.put_slide(block, gl, slide)
        return ok & np.isfinite(wx) & np.isfinite(wy)

    def _do_prp(self, step, st, q, w, al):
        (b1, b2), (g1, g2), joint = step.links, step.get("guides"), step.get("joint")
        Q1, e1, vQ1, aQ1, w1, a1 = self._guide_state(st, g1)
        Q2, e2, vQ2, aQ2, w2, a2 = self._guide_state(st, g2)
        s1, s2, det = _g.prp_position(*_re_im(Q2 - Q1), *_re_im(e1), *_re_im(e2))
        P3 = Q1 + s1 * e1
        sl1 = Slide(s=s1, direction=np.broadcast_to(e1, np.shape(s1)))
        sl2 = Slide(s=s2, direction=np.broadcast_to(e2, np.shape(s2)))
        v3 = a3 = None
        if st.order >= 1:
            ds1, ds2 = _g.prp_velocity(*_re_im(e1), *_re_im(e2), s1, s2, *_re_im(vQ1), *_re_im(vQ2), w1, w2)
            v3 = _cx(*_g.slide_velocity(*_re_im(vQ1), *_re_im(e1), s1, ds1, w1))
            sl1, sl2 = Slide(s1, sl1.direction, ds1), Slide(s2, sl2.direction, ds2)
        if st.order >= 2:
            dds1, dds2 = _g.prp_acceleration(*_re_im(e1), *_re_im(e2), s1, s2, *_re_im(aQ1), *_re_im(aQ2),
                                             w1, w2, a1, a2, ds1, ds2)
            ax, ay, k1x, k1y = _g.slide_acceleration(*_re_im(aQ1), *_re_im(e1), s1, ds1, dds1, w1, a1)
            a3 = ax + 1j * ay
            _, _, k2x, k2y = _g.slide_acceleration(*_re_im(aQ2), *_re_im(e2), s2, ds2, dds2, w2, a2)
            sl1 = Slide(s1, sl1.direction, ds1, dds1, k1x + 1j * k1y)
            sl2 = Slide(s2, sl2.direction, ds2, dds2, k2x + 1j * k2y)
        st.put_link(b1, joint, e1, w1 if st.order >= 1 else None, a1 if st.order >= 2 else None)
        st.put_link(b2, joint, e2, w2 if st.order >= 1 else None, a2 if st.order >= 2 else None)
        st.put_point(joint, P3, v3, a3)
        st.put_slide(b1, g1.link, sl1)
        st.put_slide(b2, g2.link, sl2)
        return np.abs(det) > 1e-12

    def _do_rpp(self, step, st, q, w, al):
        (pinned, sliding), p1, guide, gam, pt, e0 = (step.links, step.get("pin"), step.get("guide"),
                                                     step.get("angle"), step.get("point"), step.get("offset"))
        Q, e, vQ, aQ, wK, aK = self._guide_state(st, guide)
        wdir = e * np.exp(1j * gam)
        P1 = st.P[p1]
        s2, t, det = _g.rpp_position(*_re_im(P1 - Q), *_re_im(e), *_re_im(wdir), e0)
        J = Q + s2 * e
        slo = Slide(s=s2, direction=np.broadcast_to(e, np.shape(s2)))
        sli = Slide(s=t, direction=np.broadcast_to(wdir, np.shape(t)))
        vJ = aJ = None
        if st.order >= 1:
            ds2, dt = _g.rpp_velocity(*_re_im(e), *_re_im(wdir), s2, t, e0, *_re_im(st.V[p1]), *_re_im(vQ), wK)
            vJ = _cx(*_g.slide_velocity(*_re_im(vQ), *_re_im(e), s2, ds2, wK))
            slo, sli = Slide(s2, slo.direction, ds2), Slide(t, sli.direction, dt)
        if st.order >= 2:
            dds2, ddt, k2x, k2y, kix, kiy = _g.rpp_acceleration(
                *_re_im(e), *_re_im(wdir), s2, t, e0, *_re_im(st.A[p1]), *_re_im(aQ), wK, aK, ds2, dt)
            ax, ay, _, _ = _g.slide_acceleration(*_re_im(aQ), *_re_im(e), s2, ds2, dds2, wK, aK)
            aJ = ax + 1j * ay
            slo = Slide(s2, slo.direction, ds2, dds2, k2x + 1j * k2y)
            sli = Slide(t, sli.direction, dt, ddt, kix + 1j * kiy)
        rate = (wK if st.order >= 1 else None, aK if st.order >= 2 else None)
        st.put_link(sliding, pt, e, *rate)
        st.put_link(pinned, p1, wdir, *rate)
        st.put_point(pt, J, vJ, aJ)
        st.put_slide(sliding, guide.link, slo)
        st.put_slide(pinned, sliding, sli)
        return np.abs(det) > 1e-12

    # ------------------------------------------------------------------ centres
    def _direct_pairs(self):
        """(kind, link_i, link_j, where) for every pair of the linkage, in building order.

        ``where`` is a point name for a revolute pair, or ``(group_kind, index)`` naming the
        sliding direction of a sliding pair (resolved against a solution).
        """
        owner = self._points
        out = []
        for st in self._steps:
            k, L = st.kind, st.links
            if k == "crank":
                out.append(("R", L[0], owner[st.get("pivot")], st.get("pivot")))
            elif k == "slider":
                out.append(("P", L[0], L[1], (L[0], L[1])))
            elif k == "rrr":
                (p1, p2), j = st.get("pins"), st.get("joint")
                out += [("R", L[0], owner[p1], p1), ("R", L[1], owner[p2], p2), ("R", L[0], L[1], j)]
            elif k == "rrp":
                p1, g, j = st.get("pin"), st.get("guide"), st.get("joint")
                out += [("R", L[0], owner[p1], p1), ("R", L[0], L[1], j), ("P", L[1], g.link, (L[1], g.link))]
            elif k == "rpr":
                p1, p2 = st.get("pins")
                out += [("R", L[0], owner[p1], p1), ("R", L[1], owner[p2], p2), ("P", L[1], L[0], (L[1], L[0]))]
            elif k == "prp":
                g1, g2 = st.get("guides")
                out += [("P", L[0], g1.link, (L[0], g1.link)), ("P", L[1], g2.link, (L[1], g2.link)),
                        ("R", L[0], L[1], st.get("joint"))]
            elif k == "rpp":
                p1, g = st.get("pin"), st.get("guide")
                out += [("R", L[0], owner[p1], p1), ("P", L[1], g.link, (L[1], g.link)),
                        ("P", L[0], L[1], (L[0], L[1]))]
        return out

    # ------------------------------------------------------------------ ranges
    def assembly_range(self, driver=None, *, start=-math.pi, end=math.pi, samples=3601, others=None):
        """Intervals of one driver's input where the linkage assembles.

        The input is sampled ``samples`` times on ``[start, end]`` (other drivers held at
        ``others``), and each boundary between assembling and failing samples is refined
        by bisection to rounding. An interval shorter than the sample spacing can be
        missed; raise ``samples`` for such linkages.

        Returns
        -------
        tuple of AssemblyInterval
        """
        if driver is None:
            if len(self._drivers) != 1:
                raise ValueError(f"Expected `driver` among {list(self._drivers)}, got None")
            driver = self._drivers[0]
        if driver not in self._drivers:
            raise ValueError(f"Expected `driver` among {list(self._drivers)}, got {driver!r}")
        start, end = real_number("start", start), real_number("end", end)
        samples = integer("samples", samples, minimum=2, maximum=MAX_COUNT)
        if others is not None and not hasattr(others, "items"):
            raise InputTypeError(f"Expected `others` to be a mapping of drivers to inputs, got {others!r}")
        fixed = dict(others or {})

        def ok(x):
            return self.solve({**fixed, driver: x}, order=0).valid

        x = np.linspace(start, end, samples)
        good = ok(x)
        edges = np.flatnonzero(np.diff(good.astype(np.int8)))
        cuts = []
        for i in edges:
            lo, hi = x[i], x[i + 1]          # good[i] != good[i + 1]
            g_lo = good[i]
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                if mid in (lo, hi):
                    break
                if ok(np.array([mid]))[0] == g_lo:
                    lo = mid
                else:
                    hi = mid
            cuts.append(lo if g_lo else hi)
        out, inside, begin = [], bool(good[0]), float(x[0])
        for c in cuts:
            if inside:
                out.append(AssemblyInterval(begin, float(c)))
            else:
                begin = float(c)
            inside = not inside
        if inside:
            out.append(AssemblyInterval(begin, float(x[-1])))
        return tuple(out)


def _cx(x, y):
    return x + 1j * y


def _dead_point(st, step, disc, dead):
    """A radicand within rounding of zero at a dead point counts as zero (the dead point).

    Not next to a change point (where the group's mode flips and the solution passes):
    there `_signed_root` handles it. Returns the radicand and the dead-point mask.
    """
    _, near = st.modes.get(step.label, (step.get("branch"), None))
    if near is not None:
        dead = dead & ~near
    return np.where(dead & (disc < 0), 0.0, disc), dead


def _signed_root(st, step, disc):
    """The root of a group's radicand with the sign of its mode, and where it assembles.

    The mode comes from `mech.planar.kinematics._linkage_modes.modes`; next to a change point a
    radicand that rounding made slightly negative counts as zero.
    """
    sign, near = st.modes.get(step.label, (step.get("branch"), None))
    if near is not None:
        disc = np.where(near & (disc < 0), 0.0, disc)
    return sign * np.sqrt(disc), disc >= 0


# step data that hold lengths (or guides through fixed points); the rest are angles, signs, names
_LENGTH_KEYS = frozenset({"at", "length", "lengths", "offset", "guide", "guides"})


def _magnitudes(value, planar=False):
    """The length magnitudes held by one item of step data (a Guide, a number, a tuple).

    A point gives its two coordinates, or with ``planar=True`` its distance from the origin.
    """
    if isinstance(value, Guide):
        return [] if isinstance(value.through, str) else _magnitudes(complex(value.through), planar)
    if isinstance(value, tuple):
        return [m for v in value for m in _magnitudes(v, planar)]
    if isinstance(value, complex):
        return [math.hypot(value.real, value.imag)] if planar else [abs(value.real), abs(value.imag)]
    if isinstance(value, float):
        return [abs(value)]
    return []           # a driver's name in place of a length


def _in_unit(value, unit):
    """Divide the lengths in one item of step data by `unit` (angles and names unchanged)."""
    if isinstance(value, Guide):
        if isinstance(value.through, str):
            return value
        return replace(value, through=complex(value.through) / unit)
    if isinstance(value, tuple):
        return tuple(_in_unit(v, unit) for v in value)
    if isinstance(value, (complex, float)) and not isinstance(value, bool):
        return value / unit
    return value


class _State:
    """Mutable arrays filled step by step during one solve."""

    def __init__(self, order, shape):
        self.order, self.shape = order, shape
        self.P, self.V, self.A = {}, {}, {}
        self.dir, self.origin, self.W, self.AL = {"ground": 1.0 + 0j}, {"ground": None}, {}, {}
        self.slides = {}
        self.valid = np.ones(shape, dtype=bool)

    def drop_unfinished(self):
        """Count a pose as failed where any result is not finite (never NaN with valid True)."""
        for table in (self.P, self.V, self.A, self.W, self.AL):
            for v in table.values():
                if v is not None:
                    self.valid = self.valid & np.isfinite(v)
        for sl in self.slides.values():
            for v in (sl.s, sl.v, sl.a, sl.coriolis):
                if v is not None:
                    self.valid = self.valid & np.isfinite(v)

    def rescale(self, unit):
        """Multiply every length, linear rate and slide back from the solving unit."""
        if unit == 1.0:
            return
        with np.errstate(over="ignore", invalid="ignore"):      # NaN and inf where not assembled
            for table in (self.P, self.V, self.A):
                for k in table:
                    table[k] = table[k] * unit
            for key, sl in self.slides.items():
                self.slides[key] = Slide(*(x if x is None or i == 1 else x * unit
                                           for i, x in enumerate((sl.s, sl.direction, sl.v, sl.a, sl.coriolis))))

    def put_point(self, name, z, v, a):
        self.P[name] = z
        if self.order >= 1:
            self.V[name] = 0.0 if v is None else v
        if self.order >= 2:
            self.A[name] = 0.0 if a is None else a

    def put_link(self, link, origin, direction, w, a):
        if link == GROUND:
            return
        self.dir[link], self.origin[link] = direction, origin
        if self.order >= 1:
            self.W[link] = w
        if self.order >= 2:
            self.AL[link] = a

    def put_slide(self, moving, guiding, slide):
        self.slides[(moving, guiding)] = slide

    def rigid_v(self, origin, link, z):
        if origin is None:
            return 0.0
        return _cx(*_g.rigid_body_velocity(*_re_im(self.V[origin]), *_re_im(z - self.P[origin]), self.W[link]))

    def rigid_a(self, origin, link, z):
        if origin is None:
            return 0.0
        return _cx(*_g.rigid_body_acceleration(*_re_im(self.A[origin]), *_re_im(z - self.P[origin]),
                                               self.W[link], self.AL[link]))


class LinkageSolution:
    """The solved linkage over an array of inputs (immutable).

    Attributes
    ----------
    points, velocities, accelerations : mapping of str to complex ndarray
        Every named point; velocities need ``order >= 1``, accelerations ``order >= 2``.
    angles, omegas, alphas : mapping of str to float ndarray
        Every moving link's angle (of its frame's x axis, in (-pi, pi]; use
        ``numpy.unwrap`` along the input for a continuous angle), angular velocity and
        angular acceleration.
    slides : mapping of (str, str) to Slide
        Every sliding pair, keyed by (moving link, guiding link).
    valid : bool ndarray
        Where every group assembles.
    failures : mapping of str to bool ndarray
        For each driver and group, where it is the first to fail.
    """

    def __init__(self, linkage, order, state, failures):
        shape = state.shape
        full = lambda x: np.broadcast_to(np.asarray(x), shape)
        self.linkage, self.order, self.valid = linkage, order, state.valid
        self.points = MappingProxyType({k: full(v) for k, v in state.P.items()})
        self.velocities = MappingProxyType({k: full(v) for k, v in state.V.items()})
        self.accelerations = MappingProxyType({k: full(v) for k, v in state.A.items()})
        links = [k for k in linkage.links if k != GROUND]
        self._dirs = {k: full(state.dir[k]) for k in links}
        self.omegas = MappingProxyType({k: full(state.W[k]) for k in links if k in state.W})
        self.alphas = MappingProxyType({k: full(state.AL[k]) for k in links if k in state.AL})
        self.slides = MappingProxyType(dict(state.slides))
        self.failures = MappingProxyType(failures)

    @property
    def angles(self):
        """Angle of every moving link's frame, by atan2, in (-pi, pi]."""
        return MappingProxyType({k: np.angle(d) for k, d in self._dirs.items()})

    def instant_centres(self):
        """All n(n-1)/2 instant centres of the linkage at every pose, by Kennedy's theorem.

        The direct centres come from the pairs (a revolute pair at its joint, a sliding
        pair at infinity across its guide); the rest follow from the three-centre theorem
        (`mech.planar.instant_centres`, derivation :ref:`deriv-instant-centres`).

        Returns
        -------
        InstantCentres
            Indexed by pairs of link names, the ground being ``"ground"``. A centre that
            the positions do not fix (its Kennedy lines coincide at a pose) is NaN there,
            with its mask ``defined`` False.

        Raises
        ------
        ValueError
            If a pose was not assembled (its centres do not exist).
        """
        from mech.planar.kinematics._instant_centres import instant_centres, prismatic, revolute

        if not np.all(self.valid):
            first = np.unravel_index(np.flatnonzero(~self.valid)[0], self.valid.shape)
            raise ValueError(f"Expected every pose to be assembled, got an invalid pose at index "
                             f"{tuple(int(i) for i in first)}; solve the valid inputs only")
        direct = {}
        for kind, i, j, where in self.linkage._direct_pairs():
            key = (i, j)
            if (j, i) in direct or key in direct:
                continue          # a compound hinge: one pair per two links is enough
            if kind == "R":
                direct[key] = revolute(self.points[where])
            else:
                direct[key] = prismatic(self.slides[where].direction)
        return instant_centres(self.linkage.links, direct, undefined="nan")

    def direction(self, link):
        """Unit complex direction of ``link``'s frame x axis (no trigonometry)."""
        known_name("link", link, tuple(self._dirs))
        return self._dirs[link]

    def __setattr__(self, name, value):
        if name in self.__dict__:
            raise AttributeError("LinkageSolution is immutable")
        object.__setattr__(self, name, value)

    def __repr__(self):
        return (f"LinkageSolution(order={self.order}, shape={self.valid.shape}, "
                f"valid={int(self.valid.sum())}/{self.valid.size})")
