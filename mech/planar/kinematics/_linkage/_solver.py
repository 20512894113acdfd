"""Any planar linkage of revolute and sliding pairs: drivers, then class II Assur groups.

The formulas come from ``derivations/planar/assur_groups.md`` through
``mech._generated.assur_groups``; this module builds the linkage, orders the steps and
reports failures. The records it is built from and solved into are in ``_linkage_records``,
the state carried from one group to the next and the solver of each step in
``_linkage_groups``.
"""

from __future__ import annotations

import math

import numpy as np

from mech._errors import AssemblyError, InputTypeError
from mech import _backend
from mech.planar.kinematics._linkage import _blocks as _linkage_blocks, _compiled as _linkage_compiled, _modes as _linkage_modes
from mech.planar.kinematics._linkage._groups import STEPS, _State
from mech.planar.kinematics._linkage._records import (
    GROUND, AssemblyInterval, Guide, LinkageSolution, Slide, _LENGTH_KEYS, _Step, _for, _in_unit, _looks_numeric,
    _magnitudes, _two,
)
from mech._validate import (
    bool_flag, branch_sign, finite_array, integer, MAX_COUNT, nonnegative_int, planar_point, positive_length, real_number, common_shape)

__all__ = ["Linkage", "LinkageSolution", "Guide", "Slide", "AssemblyInterval"]


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
        the cache (`mech.planar.kinematics._linkage._blocks`), with the same results.

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
        if _linkage_compiled.supported(self) and _backend.use_numba(math.prod(shape), _linkage_compiled.MIN_SIZE):
            # one compiled loop over the poses, the same rules pose by pose
            state, failures = _linkage_compiled.solve(self, steps, order, shape, sq, sw, sal, crank, unit)
        elif math.prod(shape) <= _linkage_blocks.BLOCK:
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
        zero (`mech.planar.kinematics._linkage._modes.modes`).
        """
        state = _State(order, shape)
        state.modes = modes
        failures = {}
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            for step in steps:
                ok = STEPS[step.kind](step, state, q, w, al)
                if ok is not None:
                    ok = np.broadcast_to(ok, shape)
                    first = ~ok & state.valid
                    failures[step.label] = first
                    state.valid = state.valid & ok
        return state, failures

    def _crank_driver(self):
        """The driver's name when the linkage is driven by one crank, else None (cached)."""
        if "_crank_cache" not in self.__dict__:
            cranks = [s.get("driver") for s in self._steps if s.kind == "crank"]
            self._crank_cache = cranks[0] if len(self._drivers) == 1 and cranks == list(self._drivers) else None
        return self._crank_cache

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
        """Names of the drivers whose input is a distance (sliders and actuators), cached."""
        cached = self.__dict__.get("_far_cache")
        if cached is not None:
            return cached
        out = set()
        for step in self._steps:
            if step.kind == "slider":
                out.add(step.get("driver"))
            elif step.kind == "rrr":
                out.update(x for x in step.get("lengths") if isinstance(x, str))
        self._far_cache = out = frozenset(out)
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
