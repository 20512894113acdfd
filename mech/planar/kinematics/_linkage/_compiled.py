"""`Linkage.solve` as one compiled loop over the poses (the numba backend).

The NumPy path (`_linkage_groups`) solves step after step over whole arrays of inputs. Here
the same steps become the body of one numba loop that solves a pose completely before it
moves to the next, calling numba-compiled copies of the same generated functions
(``mech._generated.assur_groups``) on scalars. The source of the loop is written from the
linkage's steps: its kinds, which points and links each step reads and writes, the order
of the rates and which groups have change points. Its numbers (ground points, lengths,
local coordinates, branches, change points) are arguments, so one compiled loop serves
every linkage of the same topology (`_KERNELS`, one per process).

Every rule of the NumPy path is repeated pose by pose in the same floating-point
operations: the mode of each group from its change points (`_linkage_modes.Schedule`),
a radicand snapped onto a dead point, a slightly negative radicand next to a change point,
NaN rates at a dead point, the first group to fail, the finiteness check and the unit of
length. Poses within the bridge of a change point (interpolated across it by
`_linkage_modes.bridge`) are flagged by the loop and solved again by the NumPy path, whose
result for one pose depends on that pose alone. Only ground points, points on links,
cranks and RRR groups of fixed lengths have a loop; any other linkage stays on NumPy.
"""

from __future__ import annotations

import hashlib
import importlib.util
import math
import os
import sys

import numpy as np

from mech._scaling import DEAD_POINT_RTOL
from mech.planar.kinematics._linkage import _modes as _linkage_modes
from mech.planar.kinematics._linkage._records import GROUND

__all__ = []        # internal to the subpackage: nothing here is re-exported

#: The smallest solve that the backend ``"auto"`` hands to the loop: a linkage's NumPy path
#: makes a few hundred array operations per solve, so at a few hundred poses the loop is
#: already several times faster (once numba is loaded and the loop compiled).
MIN_SIZE = 512
#: Step kinds the loop is written for.
KINDS = frozenset({"ground", "point", "crank", "rrr"})

_KERNELS = {}       # source of a loop -> its compiled function

#: The module written for each topology: the generated functions the loop calls, the mode
#: rules and the loop, each compiled by numba with its on-disk cache, so a later process
#: loads the machine code instead of compiling it again (seconds for a six-bar at order 2).
_HEADER = """import math

import numba
import numpy as np

from mech._generated import assur_groups as _g

_jit = numba.njit(cache=True, error_model="numpy", inline="always")
rbp = _jit(_g.rigid_body_position)
rbv = _jit(_g.rigid_body_velocity)
rba = _jit(_g.rigid_body_acceleration)
rrr = _jit(_g.rrr_position)
rrr_root = _jit(_g.rrr_position_root)
rrv = _jit(_g.rrr_velocity)
rra = _jit(_g.rrr_acceleration)
"""


def supported(linkage):
    """True if every step of `linkage` has a compiled form (and every driver is a crank)."""
    known = linkage.__dict__.get("_compiled_supported")
    if known is None:
        known = linkage._compiled_supported = all(
            step.kind in KINDS and not (step.kind == "rrr" and any(isinstance(r, str) for r in step.get("lengths")))
            for step in linkage._steps)
    return known


class _Writer:
    """Source lines of the loop body and the numbers it reads from ``par``."""

    def __init__(self):
        self.lines, self.values, self.before = [], [], []

    def par(self, value):
        # read once before the loop: numba cannot tell that ``par`` is not one of the
        # outputs, so a read inside the loop would be repeated at every pose
        self.values.append(float(value))
        name = f"c{len(self.values) - 1}"
        self.before.append(f"{name} = par[{len(self.values) - 1}]")
        return name

    def add(self, *lines):
        self.lines.extend(lines)

    def hoist(self, *lines):
        """Lines computed once before the loop (from constants only)."""
        self.before.extend(lines)


def _source(linkage, steps, order, schedules, unit, drivers, dirs):
    """The loop's source for `steps` and the values of ``par``; also the output layout."""
    wr = _Writer()
    points, links, groups, scheduled = {}, {}, [], []
    origin = {}
    moving = []

    def pvar(name):
        return points[name]

    for step in steps:
        k = step.kind
        if k == "ground":
            at = step.get("at")
            points[step.label] = f"g{len(points)}"
            v = points[step.label]
            wr.add(f"{v}x = {wr.par(at.real)}", f"{v}y = {wr.par(at.imag)}")
            if order >= 1:
                wr.add(f"{v}vx = 0.0", f"{v}vy = 0.0")
            if order >= 2:
                wr.add(f"{v}ax = 0.0", f"{v}ay = 0.0")
        elif k == "crank":
            link, pivot, tip = step.links[0], pvar(step.get("pivot")), step.get("tip")
            i = drivers.index(step.get("driver"))
            L = links[link] = f"l{len(links)}"
            origin[link] = pivot
            v = points[tip] = f"p{len(points)}"
            moving.append(tip)
            wr.add(f"q = q{i}[t * q{i}s]", f"{L}dx = math.cos(q)", f"{L}dy = math.sin(q)",
                   f"{v}x, {v}y = rbp({pivot}x, {pivot}y, {L}dx, {L}dy, {wr.par(step.get('length'))}, 0.0)")
            if order >= 1:
                wr.add(f"{L}w = w{i}[t * w{i}s]",
                       f"{v}vx, {v}vy = rbv({pivot}vx, {pivot}vy, {v}x - {pivot}x, {v}y - {pivot}y, {L}w)")
            if order >= 2:
                wr.add(f"{L}al = a{i}[t * a{i}s]",
                       f"{v}ax, {v}ay = rba({pivot}ax, {pivot}ay, {v}x - {pivot}x, {v}y - {pivot}y, {L}w, {L}al)")
        elif k == "point":
            link = step.links[0]
            L, o, at = links[link], origin[link], step.get("at")
            v = points[step.label] = f"p{len(points)}"
            moving.append(step.label)
            wr.add(f"{v}x, {v}y = rbp({o}x, {o}y, {L}dx, {L}dy, {wr.par(at.real)}, {wr.par(at.imag)})")
            if order >= 1:
                wr.add(f"{v}vx, {v}vy = rbv({o}vx, {o}vy, {v}x - {o}x, {v}y - {o}y, {L}w)")
            if order >= 2:
                wr.add(f"{v}ax, {v}ay = rba({o}ax, {o}ay, {v}x - {o}x, {v}y - {o}y, {L}w, {L}al)")
        elif k == "rrr":
            (l1, l2), (p1, p2), joint = step.links, step.get("pins"), step.get("joint")
            P1, P2 = pvar(p1), pvar(p2)
            r1, r2 = (wr.par(r) for r in step.get("lengths"))
            j = len(groups)
            groups.append(step.label)
            sch = schedules.get(step.label) if schedules else None
            has = sch is not None and len(sch.points) > 0
            # the group's constants once before the loop, in the same operations as per pose
            wr.hoist(f"sum{j} = abs({r1}) + abs({r2})", f"dif{j} = abs({r1} - {r2})",
                     f"rat{j}a = 0.0 / {r1}", f"scl{j}a = 1.0 / ({r1} + 0.0 * rat{j}a)",
                     f"rat{j}b = 0.0 / {r2}", f"scl{j}b = 1.0 / ({r2} + 0.0 * rat{j}b)")
            wr.add(f"gx = {P2}x - {P1}x", f"gy = {P2}y - {P1}y",
                   "gd = np.hypot(gx, gy)",
                   f"heron = heron_of(gd, {r1}, {r2})",
                   f"size = sum{j} + gd",
                   f"tol = {DEAD_POINT_RTOL!r} * size",
                   f"dead = (abs(gd - sum{j}) <= tol) | (abs(gd - dif{j}) <= tol)")
            branch = wr.par(step.get("branch"))
            if has:
                s = len(scheduled)
                scheduled.append((step.label, sch))
                wr.add(f"sign, near, need = mode(th, {branch}, pts{s}, {wr.par(sch.period)}, "
                       f"{wr.par(sch.width)}, {wr.par(_linkage_modes._HALF * sch.width / 1.5)})",
                       "redo = redo | need",
                       "dead = dead & (not near)",
                       "if dead and heron < 0.0:", "    heron = 0.0",
                       "if near and heron < 0.0:", "    heron = 0.0",
                       "rho = sign * np.sqrt(heron)")
            else:
                wr.add("if dead and heron < 0.0:", "    heron = 0.0", f"rho = {branch} * np.sqrt(heron)")
            L1, L2 = links[l1], links[l2] = f"l{len(links)}", f"l{len(links) + 1}"
            origin[l1], origin[l2] = P1, P2
            v = points[joint] = f"p{len(points)}"
            moving.append(joint)
            wr.add(f"ux, uy = rrr_root(gx, gy, {r1}, {r2}, rho)",
                   "ok = (heron >= 0.0) & np.isfinite(ux) & np.isfinite(uy)",
                   f"fail[{j}, t] = (not ok) and good",
                   "good = good and ok",
                   f"{v}x = {P1}x + ux", f"{v}y = {P1}y + uy",
                   f"u2x = {v}x - {P2}x", f"u2y = {v}y - {P2}y",
                   f"{L1}dx, {L1}dy = cdiv(ux, uy, rat{j}a, scl{j}a)", f"{L2}dx, {L2}dy = cdiv(u2x, u2y, rat{j}b, scl{j}b)")
            if order >= 1:
                wr.add(f"{L1}w, {L2}w, {v}vx, {v}vy = rrv(ux, uy, u2x, u2y, {r1}, {r2}, {P1}vx, {P1}vy, "
                       f"{P2}vx, {P2}vy, 0.0, 0.0)")
            if order >= 2:
                wr.add(f"{L1}al, {L2}al, {v}ax, {v}ay = rra(ux, uy, u2x, u2y, {r1}, {r2}, {P1}ax, {P1}ay, "
                       f"{P2}ax, {P2}ay, 0.0, 0.0, 0.0, 0.0, {L1}w, {L2}w)")
            if order >= 1:
                wr.add("if dead:", f"    {L1}w = {L2}w = {v}vx = {v}vy = math.nan")
                if order >= 2:
                    wr.add(f"    {L1}al = {L2}al = {v}ax = {v}ay = math.nan")
    # the finiteness check before and after the change of unit, and the stores
    names = [points[m] for m in moving]
    lks = [links[k] for k in linkage.links if k != GROUND]
    rot = {k: links[k] for k in linkage.links if k != GROUND}
    rated = [links[s.links[0]] for s in steps if s.kind == "crank"]
    tables = [(names, "", "")] + ([(names, "v", "")] if order >= 1 else []) + ([(names, "a", "")] if order >= 2 else [])
    finite = [f"{n}{r}{c}" for ns, r, _ in tables for n in ns for c in "xy"]
    finite += [f"{L}w" for L in lks if L not in rated] if order >= 1 else []
    finite += [f"{L}al" for L in lks if L not in rated] if order >= 2 else []
    grounds = [points[s.label] for s in steps if s.kind == "ground"]
    finite += [f"{g}x" for g in grounds] + [f"{g}y" for g in grounds]
    wr.add("good = good and " + " and ".join(f"np.isfinite({x})" for x in finite) if finite else "pass")
    wr.add(*(f"fail[{j}, t] = fail[{j}, t] and not good" for j in range(len(groups))))
    scale = unit != 1.0
    for ns, r, _ in tables:
        out = {"": "P", "v": "V", "a": "A"}[r]
        for i, n in enumerate(ns):
            if scale:
                wr.add(f"zx = {n}{r}x * unit - {n}{r}y * 0.0", f"zy = {n}{r}x * 0.0 + {n}{r}y * unit",
                       f"good = good and np.isfinite(zx) and np.isfinite(zy)", f"{out}[{i}, t] = complex(zx, zy)")
            else:
                wr.add(f"{out}[{i}, t] = complex({n}{r}x, {n}{r}y)")
    for i, L in enumerate(lks):
        if dirs:
            wr.add(f"D[{i}, t] = complex({L}dx, {L}dy)")
        if order >= 1 and L not in rated:
            wr.add(f"W[{i}, t] = {L}w")
        if order >= 2 and L not in rated:
            wr.add(f"AL[{i}, t] = {L}al")
    wr.add("valid[t] = good")
    crank = next((drivers.index(s.get("driver")) for s in steps if s.kind == "crank"), 0)
    args = [f"{x}{i}, {x}{i}s" for i in range(len(drivers)) for x in "qwa"]
    args += [f"pts{s}" for s in range(len(scheduled))] + ["par", "unit", "P", "V", "A", "D", "W", "AL", "valid",
                                                          "fail", "redo_out"]
    body = "\n".join("        " + line for line in wr.lines)
    before = "".join(f"    {line}\n" for line in wr.before)
    src = (f"def loop({', '.join(args)}):\n{before}    for t in range(P.shape[1]):\n        good = True\n"
           f"        redo = False\n        th = q{crank}[t * q{crank}s]\n{body}\n        redo_out[t] = redo\n")
    layout = dict(moving=moving, links=[k for k in linkage.links if k != GROUND], groups=groups,
                  scheduled=scheduled, rated=[s.links[0] for s in steps if s.kind == "crank"])
    return src, np.array(wr.values), layout


def _mode_source():
    """Per pose: the sign of a group's root, whether it is next to a change point, and
    whether the bridge across one reaches it (`_linkage_modes.Schedule.flips`, ``near``,
    `_linkage_modes.bridge`), in the same operations as NumPy's."""
    return '''
def mode(theta, branch, points, period, width, bridge):
    n = points.shape[0]
    turns = math.floor(theta / period)
    rest = theta - turns * period
    passed = np.searchsorted(points, rest, side="right")
    at_zero = 1 if points[0] <= 0.0 else 0
    flips = turns * n + passed - at_zero
    odd = pymod(flips, 2.0)
    sign = branch * (1.0 - 2.0 * odd)
    near = False
    need = False
    for i in range(n):
        off = pymod(theta - points[i] + 0.5 * period, period) - 0.5 * period
        if abs(off) <= width:
            near = True
        # a margin of rounding: a pose the bridge may reach is solved again by NumPy
        if abs(off) < bridge * (1.0 + 1e-9):
            need = True
    return sign, near, need


def pymod(a, b):
    m = np.fmod(a, b)
    if m != 0.0:
        if (b < 0.0) != (m < 0.0):
            m += b
    else:
        m = math.copysign(0.0, b)
    return m


def cdiv(ar, ai, rat, scl):
    # NumPy's complex / real: rat = 0.0 / b and scl = 1.0 / (b + 0.0 * rat), made before the loop
    return (ar + ai * rat) * scl, (ai - ar * rat) * scl


def heron_of(x4, r1, r2):
    # rrr_position's Heron product from x4 = hypot(gx, gy), in its operations and order
    # (the loop has x4 already; a second call of hypot would not be merged); the tests
    # check the loop bit for bit against the NumPy path, which calls rrr_position
    x5 = r1 + r2
    x6 = (-x4 + x5)*(-r1 + r2 + x4)*(r1 - r2 + x4)
    x7 = x4 + x5
    return x6*x7
'''


def cache_dir():
    """Where the loops' modules and numba's caches of them are written.

    ``MECH_CACHE_DIR`` if set, else ``~/.cache/mech`` (``XDG_CACHE_HOME`` respected).
    """
    root = os.environ.get("MECH_CACHE_DIR")
    if not root:
        root = os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"),
                            "mech")
    return os.path.join(root, "linkage-loops")


def kernel(src):
    """The compiled loop of `src`: from this process's table, numba's disk cache, or compiled."""
    fn = _KERNELS.get(src)
    if fn is None:
        text = _HEADER + _jitted(_mode_source()) + "\n\n" + _jitted(src)
        name = "mech_linkage_loop_" + hashlib.sha256(text.encode()).hexdigest()[:20]
        try:
            folder = cache_dir()
            os.makedirs(folder, exist_ok=True)
            path = os.path.join(folder, name + ".py")
            if not os.path.exists(path):
                # written whole, then renamed: a process running at the same time reads either nothing or all
                tmp = f"{path}.{os.getpid()}.tmp"
                with open(tmp, "w") as fh:
                    fh.write(text)
                os.replace(tmp, path)
        except OSError:                 # nowhere to write: compile in memory, every process again
            path = None
        if path is None:
            scope = {}
            exec(compile(text.replace("cache=True", "cache=False"), f"<{name}>", "exec"), scope)
            fn = scope["loop"]
        else:
            spec = importlib.util.spec_from_file_location(name, path)
            module = importlib.util.module_from_spec(spec)
            # numba's cache finds the module's globals again by its name
            sys.modules[name] = module
            spec.loader.exec_module(module)
            fn = module.loop
        _KERNELS[src] = fn
    return fn


def _jitted(src):
    """Put numba's decorator on every top-level function of `src`."""
    return ("\n" + src).replace("\ndef ", '\n@numba.njit(cache=True, error_model="numpy")\ndef ')


def _column(x, shape):
    """A driver's input as a 1-d array over `shape` and its step per pose (0 for one value)."""
    x = np.asarray(x, dtype=float)
    if x.size == 1:
        return [x.reshape(1), 0]
    if x.shape != tuple(shape):
        x = np.broadcast_to(x, shape)
    return [np.ascontiguousarray(x).reshape(-1), 1]


def solve(linkage, steps, order, shape, q, w, al, crank, unit, dirs=False):
    """`Linkage._solve_all` by the compiled loop; returns (state, failures).

    The links' directions take as many bytes per pose as the points, and a caller often
    never reads them: without `dirs` the loop does not store them, and the state's
    ``dirs_later`` solves again, storing them, when the solution first needs them.
    """
    from mech.planar.kinematics._linkage._groups import _State

    drivers = list(linkage._drivers)
    cache = linkage.__dict__.setdefault("_compiled_cache", {})
    key = (order, unit, dirs)
    if key not in cache:
        schedules = linkage._schedules() if crank is not None else {}
        src, par, lay = _source(linkage, steps, order, schedules, unit, drivers, dirs)
        pts = [np.ascontiguousarray(sch.points, dtype=float) for _, sch in lay["scheduled"]]
        rated = {s.links[0]: s.get("driver") for s in steps if s.kind == "crank"}
        grounds = [(s.label, s.get("at") * unit if unit != 1.0 else s.get("at")) for s in steps if s.kind == "ground"]
        cache[key] = (kernel(src), par, lay, pts, rated, grounds, {})
    fn, par, lay, pts, rated, grounds, fixed = cache[key]
    n = math.prod(shape)
    cols = []
    for d in drivers:
        for x in (q[d], w[d], al[d]):
            cols += _column(x, shape)
    moving, lks, groups = lay["moving"], lay["links"], lay["groups"]
    P = np.empty((len(moving), n), complex)
    V = np.empty((len(moving) if order >= 1 else 0, n), complex)
    A = np.empty((len(moving) if order >= 2 else 0, n), complex)
    D = np.empty((len(lks) if dirs else 0, n), complex)
    W = np.empty((len(lks) if order >= 1 else 0, n))
    AL = np.empty((len(lks) if order >= 2 else 0, n))
    valid = np.empty(n, dtype=bool)
    fail = np.empty((len(groups), n), dtype=bool)
    redo = np.empty(n, dtype=bool)
    fn(*cols, *pts, par, float(unit), P, V, A, D, W, AL, valid, fail, redo)
    for x in (P, V, A, D, W, AL, valid, fail):
        if x.size:
            x.flags.writeable = False       # read-only, as the NumPy path's broadcast views are
    st = _State.__new__(_State)             # every field is set here: no array of ones to fill
    st.order, st.shape, st.modes, st.slides = order, shape, {}, {}
    st.P, st.V, st.A, st.W, st.AL = {}, {}, {}, {}, {}
    st.dir = {GROUND: 1.0 + 0j}
    if shape not in fixed:
        # the ground points as read-only views over the shape, made once per shape (as the
        # solution would broadcast them at every call)
        if len(fixed) > 8:
            fixed.clear()
        zero = np.broadcast_to(np.zeros(()), shape)
        fixed[shape] = [(label, np.broadcast_to(np.asarray(at), shape), zero) for label, at in grounds]
    for label, at, zero in fixed[shape]:
        st.P[label] = at
        if order >= 1:
            st.V[label] = zero
        if order >= 2:
            st.A[label] = zero
    for i, name in enumerate(moving):
        st.P[name] = P[i].reshape(shape)
        if order >= 1:
            st.V[name] = V[i].reshape(shape)
        if order >= 2:
            st.A[name] = A[i].reshape(shape)
    for i, link in enumerate(lks):
        if dirs:
            st.dir[link] = D[i].reshape(shape)
        if order >= 1:
            st.W[link] = w[rated[link]] if link in rated else W[i].reshape(shape)
        if order >= 2:
            st.AL[link] = al[rated[link]] if link in rated else AL[i].reshape(shape)
    st.origin = None
    st.valid = valid.reshape(shape)
    failures = {label: fail[j].reshape(shape) for j, label in enumerate(groups)}
    if crank is not None and lay["scheduled"] and redo.any():      # only a change point asks for NumPy
        _redo(linkage, steps, order, shape, q, w, al, crank, unit, st, failures, np.flatnonzero(redo))
    if not dirs:
        st.dirs_later = lambda: {k: v for k, v in solve(linkage, steps, order, shape, q, w, al, crank, unit,
                                                         True)[0].dir.items() if k != GROUND}
    return st, failures


def _redo(linkage, steps, order, shape, q, w, al, crank, unit, st, failures, idx):
    """Solve the poses `idx` (next to a change point) by the NumPy path and put them in place."""
    pick = {}
    for name, x in (("q", q), ("w", w), ("al", al)):
        pick[name] = {d: (np.broadcast_to(v, shape).reshape(-1)[idx] if np.size(v) != 1 else v)
                      for d, v in x.items()}
    sub, subfail = linkage._solve_all(steps, order, (idx.size,), pick["q"], pick["w"], pick["al"], crank, unit)
    for kind, table, subtable in (("P", st.P, sub.P), ("V", st.V, sub.V), ("A", st.A, sub.A),
                                  ("W", st.W, sub.W), ("AL", st.AL, sub.AL), ("dir", st.dir, sub.dir)):
        for key, value in subtable.items():
            if kind == "dir" and (key == GROUND or key not in table):
                continue            # the directions of a second pass (`solve` with `dirs`)
            table[key] = _put(table[key], value, idx, shape)
    st.valid = _put(st.valid, sub.valid, idx, shape)
    for label in failures:
        failures[label] = _put(failures[label], subfail[label], idx, shape)


def _put(current, value, idx, shape):
    """`current` (an array over `shape` or one value) with `value` written at the flat `idx`."""
    value = np.asarray(value)
    cur = np.asarray(current)
    if cur.shape != tuple(shape) or 0 in cur.strides:
        if value.ndim == 0:         # one value in the NumPy solve too: nothing was interpolated
            return current
    cur = np.array(np.broadcast_to(cur, shape), dtype=np.result_type(cur, value))
    flat = cur.reshape(-1)
    flat[idx] = np.broadcast_to(value, idx.shape)
    cur.flags.writeable = False
    return cur
