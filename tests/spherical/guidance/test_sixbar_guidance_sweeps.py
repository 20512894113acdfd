"""Acceptance sweep of the spherical six-bar guidance designs (issue 24): `guidance_watt1`,
`guidance_watt2` and `guidance_stephenson3`, for 200 task sets taken from the guided link of
random six-bars of the same type (random orientation sets seldom have a design) and 50
near-degenerate ones (two input angles 1e-6 to 1e-9 rad apart; a six-bar on a cap of
1e-2 to 1e-3 rad, near the planar limit).

Every design a function reports as passing is moved by the test's own geometry, from the
lengths it reports and never by the package's solvers:

- the dyad six-bars (`SphericalLinkage`): the crank is turned by Rodrigues' formula, each
  RRR joint is the intersection of two circles on the sphere on the side of its first pose,
  and each point on a link is carried by the rotation of that link's frame; along 1,001
  inputs from the first task angle to the last both circles must still meet (no dead point
  between the orientations, so one branch and in order);
- the Stephenson-3 (a triad, no dyad comes first): the guided link's turn is continued from
  the reported assembly in steps of 0.01 rad by Newton's method on its three constant arcs,
  written here with a finite-difference Jacobian.

The guided body must reach each task orientation to 1e-8 of the task's largest turn, and its
joints the task's positions to 1e-8 of their largest displacement over the task (so a design
on a small cap is held to its own size, not to the sphere's).
"""

import numpy as np
import pytest

from mech._errors import AssemblyError
from mech.spherical import (guidance_stephenson3, guidance_watt1, guidance_watt2, rotation_matrix,
                            sixbar_orientations, stephenson3, watt1, watt2)

TOL = 1e-8
DESIGN = {"watt1": guidance_watt1, "watt2": guidance_watt2, "stephenson3": guidance_stephenson3}


# ------------------------------------------------------------------ the test's own geometry
def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _rot(axis, angle):
    """Rodrigues' rotations about `axis` by the angles `angle` (shape (m,)), shape (m, 3, 3)."""
    k = _unit(np.asarray(axis, float))
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    t = np.asarray(angle, float)[..., None, None]
    return np.eye(3) + np.sin(t) * K + (1.0 - np.cos(t)) * (K @ K)


def _tangent(o, p):
    """Unit tangent at `o` of the great circle o -> p (stacks)."""
    return _unit(p - np.sum(o * p, axis=-1, keepdims=True) * o)


def _frame(o, p):
    """Rotation whose columns are o, the tangent toward p and their cross product."""
    t = _tangent(o, p)
    return np.stack([o, t, np.cross(o, t)], axis=-1)


def _circles(P1, P2, b1, b2, sign):
    """The joint J at arc b1 from P1 and b2 from P2 with sign det[P1, P2, J] = sign, and a
    margin that is negative where the two circles do not meet.

    The angle phi at P1 between the great circles to P2 and to J comes from the haversine
    rule, hav(phi) = sin((b2 - b1 + d)/2) sin((b2 + b1 - d)/2) / (sin b1 sin d) with d the
    arc P1 P2: a product of sines, so small arcs (a linkage on a small cap) keep their
    digits, where the cosines of the arcs would lose them."""
    P1, P2 = _unit(P1), _unit(P2)
    cross = np.cross(P1, P2)
    s = np.linalg.norm(cross, axis=-1)
    d = np.arctan2(s, np.sum(P1 * P2, axis=-1))
    hav = np.sin((b2 - b1 + d) / 2) * np.sin((b2 + b1 - d) / 2) / (np.sin(b1) * np.sin(d))
    phi = sign * 2.0 * np.arcsin(np.sqrt(np.clip(hav, 0.0, 1.0)))
    w = cross / s[..., None]
    u = np.cross(w, P1)
    J = np.cos(b1) * P1 + np.sin(b1) * (np.cos(phi)[..., None] * u + np.sin(phi)[..., None] * w)
    return J, np.minimum(hav, 1.0 - hav)


def _move_chain(linkage, inputs):
    """Positions of every point of a crank-and-dyads linkage at the crank inputs, from its
    reported steps (arcs, angles, branch signs) by the geometry above; and the smallest
    radicand of its dyads at each input."""
    m = inputs.size
    pts, frames, worst = {}, {}, np.full(m, np.inf)
    for step in linkage._steps:
        kind = step[0]
        if kind == "ground":
            pts[step[1]] = np.broadcast_to(_unit(np.asarray(step[2], float)), (m, 3))
        elif kind == "crank":
            _, link, pivot, tip, arc, ref = step
            A, Dr = pts[pivot][0], pts[ref][0]
            start = np.cos(arc) * A + np.sin(arc) * _tangent(A, Dr)
            pts[tip] = np.einsum("mij,j->mi", _rot(A, inputs), start)
            frames[link] = (pivot, tip)
        elif kind == "rrr":
            _, (l1, l2), (p1, p2), joint, (b1, b2), sign = step
            pts[joint], rad = _circles(pts[p1], pts[p2], b1, b2, sign)
            worst = np.minimum(worst, rad)
            frames[l1], frames[l2] = (p1, joint), (p2, joint)
        elif kind == "point":
            _, name, link, r, gam = step
            o, t = frames[link]
            O = pts[o]
            local = np.cos(r) * O + np.sin(r) * _tangent(O, pts[t])
            pts[name] = np.stack([_rot(O[k], [gam])[0] @ local[k] for k in range(m)])
        else:  # pragma: no cover - a step this test does not know
            raise AssertionError(f"unknown step {kind!r}")
    return pts, worst


def _gap(Ra, Rb):
    """Angle of Ra Rb^T (stacks), from the difference so that small gaps keep their digits."""
    return 2.0 * np.arcsin(np.minimum(1.0, np.linalg.norm(Ra - Rb, axis=(-2, -1)) / np.sqrt(8.0)))


def _task_size(R):
    return max(float(_gap(R[i], R[k])) for i in range(len(R)) for k in range(i + 1, len(R)))


def _misses(R, got, joints_got, joints_task):
    """How far the guided body misses the task: orientation gaps over the task's largest
    turn, joint gaps over each joint's largest displacement over the task."""
    out = []
    rel = _gap(got, R) / _task_size(R)
    if not np.all(rel <= TOL):
        out.append(f"orientation off by {np.nanmax(rel):.3g} of the largest turn")
    for name, p in joints_task.items():
        spread = max(np.linalg.norm(a - b) for a in p for b in p)
        rel = np.linalg.norm(joints_got[name] - p, axis=-1) / spread
        if not np.all(rel <= TOL):
            out.append(f"joint {name} off by {np.nanmax(rel):.3g} of its displacement")
    return out


def _check_chain(d, R, theta):
    """A Watt-1 or Watt-2 design moved by the test's geometry through the task."""
    out = []
    pts, _ = _move_chain(d.linkage, np.array([theta[0] + d.input_offset]))
    for k, v in d.points.items():                       # the reported lengths rebuild the reported pose
        if not np.linalg.norm(pts[k][0] - v) <= 1e-9:
            out.append(f"joint {k} rebuilt {np.linalg.norm(pts[k][0] - v):.3g} away from the reported pose")
    pts, rad = _move_chain(d.linkage, theta + d.input_offset)
    sweep = np.linspace(theta[0], theta[-1], 1001) + d.input_offset
    if not np.all(_move_chain(d.linkage, sweep)[1] > 0.0):
        out.append("a dyad cannot close between the first and the last orientation")
    E1, G1 = pts["E"][0], pts["G"][0]
    got = _frame(pts["E"], pts["G"]) @ _frame(E1, G1).T @ R[0]
    D = R @ R[0].T                                       # displacements of the task
    task = {"E": D @ E1, "G": D @ G1}
    return out + _misses(R, got, {"E": pts["E"], "G": pts["G"]}, task)


def _turned(p, A, t):
    return _rot(A, [t])[0] @ p


def _closure(P, Q, turn, cosines):
    B, E = _turned(P["B"], P["A"], turn), _turned(P["E"], P["A"], turn)
    return np.array([B @ Q @ P["C"], E @ Q @ P["G"], P["D"] @ Q @ P["H"]]) - cosines


def _newton(P, Q, turn, cosines):
    for _ in range(30):
        r = _closure(P, Q, turn, cosines)
        if np.max(np.abs(r)) < 1e-15:
            break
        h = 1e-7                                           # central differences in the turn vector
        J = np.stack([(_closure(P, _rot(e, [h])[0] @ Q, turn, cosines)
                       - _closure(P, _rot(e, [-h])[0] @ Q, turn, cosines)) / (2 * h) for e in np.eye(3)], axis=1)
        w = np.linalg.solve(J, -r)
        Q = _rot(w, [np.linalg.norm(w)])[0] @ Q if np.linalg.norm(w) > 0 else Q
    return Q, float(np.max(np.abs(_closure(P, Q, turn, cosines))))


def _check_stephenson3(d, R, theta):
    """A Stephenson-3 design continued by the test's own Newton steps through the task."""
    lk = d.linkage
    P = lk.assembly
    out = []
    arcs = {"BC": ("B", "C"), "EG": ("E", "G"), "DH": ("D", "H")}
    for name, (p, q) in arcs.items():
        if not abs(np.arccos(np.clip(P[p] @ P[q], -1, 1)) - lk.arcs[name]) <= 1e-9:
            out.append(f"arc {name} of the assembly differs from the reported one")
    cosines = np.cos([lk.arcs["BC"], lk.arcs["EG"], lk.arcs["DH"]])
    if not np.all(np.abs(_closure(P, np.eye(3), 0.0, cosines)) <= 1e-12):
        out.append("the reported assembly does not close")
    Q, turns, got = np.eye(3), theta - theta[0], []
    t = 0.0
    for target in turns:
        while t < target:
            t = min(target, t + 0.01)
            Q, res = _newton(P, Q, t, cosines)
            if not res <= 1e-12:
                return out + [f"the continuation does not close at turn {t:.4f} ({res:.3g})"]
        got.append(Q)
    Q = np.array(got)
    body = np.array(Q) @ d.first_orientation
    D = R @ R[0].T
    task = {k: D @ P[k] for k in "CGH"}
    joints = {k: np.einsum("mij,j->mi", Q, P[k]) for k in "CGH"}
    if not np.abs(d.first_orientation - R[0]).max() <= TOL:
        out.append("the first orientation of the assembly is not the task's")
    return out + _misses(R, body, joints, task)


def _problems(kind, R, theta, pivot):
    try:
        designs = DESIGN[kind](R, theta, pivot)
    except ValueError:
        return 0, []
    passing = [d for d in designs if d.passes]
    check = _check_stephenson3 if kind == "stephenson3" else _check_chain
    out = []
    for k, d in enumerate(passing):
        out += [f"design {k}: {p}" for p in check(d, R, theta)]
    return len(passing), out


# ------------------------------------------------------------------ tasks from random six-bars
def _random_rotation(rng):
    return rotation_matrix(rng.normal(size=3), rng.uniform(0.0, np.pi))


def _six_bar(kind, rng, cap):
    frame = _random_rotation(rng)
    sign = lambda: int(rng.choice([-1, 1]))  # noqa: E731
    if kind == "stephenson3":
        a = cap * rng.uniform(0.2, 0.4)
        b, c, d = cap * rng.uniform(0.6, 1.2, 3)
        return stephenson3(a, b, c, d, E=(cap * rng.uniform(0.3, 0.7), rng.uniform(-np.pi, np.pi)),
                           arcs=tuple(cap * rng.uniform(0.6, 1.1, 2)),
                           H=(cap * rng.uniform(0.3, 0.7), rng.uniform(-np.pi, np.pi)), coupler=(0.1, 0.2),
                           mu=rng.uniform(-np.pi, np.pi), branch=sign(), frame=frame)
    a = cap * rng.uniform(0.2, 0.4)
    b, c, d = cap * rng.uniform(0.6, 1.2, 3)
    E = (cap * rng.uniform(0.3, 0.8), rng.uniform(-np.pi, np.pi))
    F = (cap * rng.uniform(0.3, 0.8) if kind == "watt1" else cap * rng.uniform(0.6, 1.4), rng.uniform(-np.pi, np.pi))
    make = watt1 if kind == "watt1" else watt2
    return make(a, b, c, d, E=E, F=F, arcs=tuple(cap * rng.uniform(0.5, 1.0, 2)), coupler=(0.1, 0.2),
                branches=(sign(), sign()), frame=frame)


def _task(kind, rng, near=None):
    """A task (R, theta, crank pivot) from the guided link of a random six-bar: five input
    angles spread over up to 300 deg on one assembled branch. `near` = ("close", gap): two
    input angles `gap` apart; ("cap", s): the six-bar on a cap of s rad."""
    cap = near[1] if near and near[0] == "cap" else 1.0
    while True:
        try:
            lk = _six_bar(kind, rng, cap)
        except AssemblyError:
            continue
        theta = np.sort(rng.uniform(0.0, np.radians(300.0), 5))
        if near and near[0] == "close":
            k = int(rng.integers(0, 4))
            theta[k + 1] = theta[k] + near[1]
        if np.min(np.diff(theta)) <= 0.0:
            continue
        if kind == "stephenson3":
            theta = theta + lk.theta0                    # its inputs are measured from A -> D too
            if not np.all(lk.solve(np.linspace(theta[0], theta[-1], 200)).valid):
                continue
            R, pivot = lk.orientations(theta), lk.assembly["A"]
        else:
            if not np.all(lk.solve(np.linspace(theta[0], theta[-1], 400)).valid):
                continue
            R, pivot = sixbar_orientations(lk, theta), lk.solve(0.0).points["A"]
        if not np.all(np.isfinite(R)):
            continue
        return R @ _random_rotation(rng), theta, pivot   # any body frame on the guided link


def _tasks(kind, n_random, n_near, seed):
    rng = np.random.default_rng(seed)
    out = [_task(kind, rng) for _ in range(n_random)]
    for k in range(n_near):
        near = ("close", 10.0 ** -rng.uniform(6, 9)) if k % 2 == 0 else ("cap", 10.0 ** -rng.uniform(2, 3))
        out.append(_task(kind, rng, near))
    return out


def _sweep(kind, n_random, n_near, seed):
    passing, wrong = 0, {}
    for k, (R, theta, pivot) in enumerate(_tasks(kind, n_random, n_near, seed)):
        count, problems = _problems(kind, R, theta, pivot)
        passing += count
        if problems:
            wrong[k] = problems
    return passing, wrong


# Open defects of issue 24, found by this sweep and not yet fixed: kept visible as expected
# failures, so that `make test-exhaustive` reports them and reports a fix (XPASS).
_OPEN = {
    "watt2": "random set 104: design 18 passes, but its lengths rebuild E and G 7e-7 from its first pose",
    "stephenson3": "random set 7 does not close at a crank turn of 0.836 (a missed dead point?); "
                   "near-planar set 3 misses H by 1.13e-8 of its displacement (an absolute 1e-9 rad pass test)",
}


@pytest.mark.exhaustive
@pytest.mark.parametrize("kind", [pytest.param(k, marks=pytest.mark.xfail(reason=_OPEN[k], strict=False))
                                  if k in _OPEN else k for k in DESIGN])
def test_sixbar_guidance_sweep(kind):
    passing, wrong = _sweep(kind, 200, 50, seed=24)
    assert passing >= 200
    assert not wrong, wrong
