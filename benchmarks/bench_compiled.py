"""Benchmark: the compiled `Linkage` loop and the batch four-bar against plain compiled loops (issue 30).

Timed as a user's script sees them: each measurement in a new Python process (``--worker``)
that builds its subject, makes one untimed call (numba's loading or compiling, the first
touch of memory) and times ``CALLS`` calls; the processes of all methods are interleaved
round after round, and each row is the median of ``ROUNDS x CALLS`` timings. The load
average is recorded at the start and the end: only the ratios within one run mean anything
on a shared machine.

References (written here, independent of ``mech``'s generated functions):

- ``*-plain``: a numba loop of plain circle intersections over the poses of the same
  linkage (Jansen's leg, the Watt six-bar), written from its steps: for each RRR group
  ``a = (r1^2 - r2^2 + g^2) / 2 g^2``, ``h = sqrt(r1^2 / g^2 - a^2)``, the joint at
  ``P1 + a g + h i g``; the points of every step stored as complex rows;
- ``batch-plain``: a numba loop over L four-bars x K angles of the same circle
  intersection (B, C and the coupler point P).

- ``rssr-plain``: a numba loop of the RSSR's closed form (2-69) to (2-71) written out here
  (A, B, C, the plain discriminant, the atan2 root, the pins and the coupler point);
- ``chain-plain``: a numba loop of the open chain's product (2-73) of H-D matrices (2-67)
  written out here (the end frame and the end point), on example 2-25's manipulator.

Both spatial loops are checked against ``mech`` (to 1e-14 of the size) before timing.

Subjects: ``Linkage.solve`` with the default backend (``auto``), ``RSSR.solve`` and
``OpenChain.solve`` (positions) with ``auto`` and with ``numpy``, and ``solve_fourbars`` on
each backend (``batch-numba``, ``batch-numpy``).

    python benchmarks/bench_compiled.py                 # N = 10^3, 10^4, 10^6, batch 10^5 x 128
    python benchmarks/bench_compiled.py --quick         # smaller, one round
    python benchmarks/bench_compiled.py --only spatial  # RSSR and OpenChain only
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
ROUNDS, CALLS = 3, 5
BATCH = (10**5, 128)


def plain_linkage_loop(linkage):
    """A numba loop of plain circle intersections over the poses of a crank-and-RRR linkage."""
    import numba

    index, lines = {}, []

    def var(name):
        return index.setdefault(name, f"p{len(index)}")

    for step in linkage._steps:
        if step.kind == "ground":
            z, v = complex(step.get("at")), var(step.label)
            lines += [f"{v}x = {z.real!r}", f"{v}y = {z.imag!r}"]
        elif step.kind == "crank":
            link, pv, tip, r = step.links[0], var(step.get("pivot")), var(step.get("tip")), step.get("length")
            lines += [f"c_{link} = math.cos(theta[t])", f"s_{link} = math.sin(theta[t])",
                      f"{tip}x = {pv}x + {r!r} * c_{link}", f"{tip}y = {pv}y + {r!r} * s_{link}"]
        elif step.kind == "rrr":
            (l1, l2), (p1, p2), j = step.links, step.get("pins"), var(step.get("joint"))
            (r1, r2), p1, p2 = step.get("lengths"), var(p1), var(p2)
            lines += [f"gx = {p2}x - {p1}x", f"gy = {p2}y - {p1}y", "gg = gx * gx + gy * gy",
                      f"a = ({r1 * r1!r} - {r2 * r2!r} + gg) / (2.0 * gg)",
                      f"h = {float(step.get('branch'))!r} * math.sqrt({r1 * r1!r} / gg - a * a)",
                      f"{j}x = {p1}x + a * gx - h * gy", f"{j}y = {p1}y + a * gy + h * gx",
                      f"c_{l1} = ({j}x - {p1}x) / {r1!r}", f"s_{l1} = ({j}y - {p1}y) / {r1!r}",
                      f"c_{l2} = ({j}x - {p2}x) / {r2!r}", f"s_{l2} = ({j}y - {p2}y) / {r2!r}"]
        elif step.kind == "point":
            link, at = step.links[0], complex(step.get("at"))
            origin = next(s for s in linkage._steps if link in s.links and s.kind in ("crank", "rrr"))
            o = var(origin.get("pivot") if origin.kind == "crank" else origin.get("pins")[origin.links.index(link)])
            v = var(step.label)
            lines += [f"{v}x = {o}x + c_{link} * {at.real!r} - s_{link} * {at.imag!r}",
                      f"{v}y = {o}y + s_{link} * {at.real!r} + c_{link} * {at.imag!r}"]
        else:
            raise ValueError(f"no plain loop for a {step.kind} step")
    names = list(index)
    body = "\n".join("        " + line for line in lines)
    stores = "\n".join(f"        out[{k}, t] = complex({index[m]}x, {index[m]}y)" for k, m in enumerate(names))
    scope = {"math": math}
    exec(f"def loop(theta, out):\n    for t in range(theta.shape[0]):\n{body}\n{stores}\n", scope)
    loop = numba.njit(error_model="numpy")(scope["loop"])
    return lambda theta: _rows(loop, len(names), theta)


def _rows(loop, count, theta):
    """Run `loop` into `count` new complex rows over the poses; return them."""
    out = np.empty((count, theta.size), complex)
    loop(theta, out)
    return out


def plain_batch_loop():
    """A numba loop over L four-bars x K angles: B, C and P by a plain circle intersection."""
    import numba

    @numba.njit(error_model="numpy")
    def loop(a, b, c, d, p, q, br, theta, B, C, P):
        for i in range(a.shape[0]):
            for t in range(theta.shape[0]):
                bx, by = a[i] * math.cos(theta[t]), a[i] * math.sin(theta[t])
                gx, gy = d[i] - bx, -by
                gg = gx * gx + gy * gy
                s = (b[i] * b[i] - c[i] * c[i] + gg) / (2.0 * gg)
                h = br[i] * math.sqrt(b[i] * b[i] / gg - s * s)
                cx, cy = bx + s * gx - h * gy, by + s * gy + h * gx
                ux, uy = (cx - bx) / b[i], (cy - by) / b[i]
                B[i, t] = complex(bx, by)
                C[i, t] = complex(cx, cy)
                P[i, t] = complex(bx + p[i] * ux - q[i] * uy, by + p[i] * uy + q[i] * ux)

    def run(dims, theta):
        n, k = dims[0].size, theta.size
        B, C, P = (np.empty((n, k), complex) for _ in range(3))
        loop(*dims, theta, B, C, P)
        return B, C, P

    return run


def rssr_subject():
    """The RSSR of the benchmark (no change points: it assembles over part of the turn) and
    its dimensions ``l1, l2, l3, s0, s3, h0, lam, p`` (coupler point at p along BC)."""
    from mech.spatial._rssr import RSSR

    dims = (2.0, 2.5, 1.5, 0.3, -0.4, 1.5, 0.8, 1.2)
    return RSSR(*dims[:7], coupler=(dims[7], 0.0, 0.0)), dims


def plain_rssr_loop(dims, sigma=1.0):
    """A numba loop of (2-69) to (2-71) written out here: A, B, C, the plain discriminant
    A^2 + B^2 - C^2, the root in atan2 form, the pins B, C and the coupler point."""
    import numba

    l1, l2, l3, s0, s3, h0, lam, p = dims
    cl, sl, k = math.cos(lam), math.sin(lam), p / l2
    K = s0 * s3 * cl / (l1 * l3) - (h0 * h0 + l1 * l1 - l2 * l2 + l3 * l3 + s0 * s0 + s3 * s3) / (2.0 * l1 * l3)

    @numba.njit(error_model="numpy")
    def loop(theta, phi03, B, C, P):
        for t in range(theta.shape[0]):
            c, s = math.cos(theta[t]), math.sin(theta[t])
            a = h0 / l1 - c
            b = s0 * sl / l1 - cl * s
            cc = K + (h0 * c + s3 * s * sl) / l3
            disc = a * a + b * b - cc * cc
            r = sigma * math.sqrt(disc) if disc >= 0.0 else math.nan
            psi = math.atan2(a * r + b * cc, a * cc - b * r)
            bx, by, bz = l1 * c, l1 * s, s0
            u = l3 * math.sin(psi)
            cx, cy, cz = h0 + l3 * math.cos(psi), s3 * sl + cl * u, s3 * cl - sl * u
            phi03[t] = psi
            B[t, 0], B[t, 1], B[t, 2] = bx, by, bz
            C[t, 0], C[t, 1], C[t, 2] = cx, cy, cz
            P[t, 0], P[t, 1], P[t, 2] = bx + k * (cx - bx), by + k * (cy - by), bz + k * (cz - bz)

    def run(theta):
        n = theta.size
        out = (np.empty(n), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3)))
        loop(theta, *out)
        return out

    return run


def chain_subject():
    """Example 2-25's four-joint manipulator (R, R, P, R) and the end point of the benchmark."""
    from mech.spatial._chain import example_2_25_manipulator

    return example_2_25_manipulator(0.5), (0.0, 0.0, 0.1)


def plain_chain_loop(chain, point):
    """A numba loop of the product (2-73) of H-D matrices (2-67) written out here, per pose:
    the end frame M (3 x 4 stored in a 4 x 4) and the end point."""
    import numba

    table = np.array([[j.phi, j.lam, j.s, j.h, j.kind in "RHC", j.kind in "PC", j.pitch / (2 * math.pi)]
                      for j in chain.joints])
    px, py, pz = point

    @numba.njit(error_model="numpy")
    def loop(q, M, P):
        for t in range(q.shape[0]):
            a00, a01, a02, a03 = 1.0, 0.0, 0.0, 0.0
            a10, a11, a12, a13 = 0.0, 1.0, 0.0, 0.0
            a20, a21, a22, a23 = 0.0, 0.0, 1.0, 0.0
            col = 0
            for k in range(table.shape[0]):
                phi, s = table[k, 0], table[k, 2]
                if table[k, 4] != 0.0:
                    phi += q[t, col]
                    s += table[k, 6] * q[t, col]
                    col += 1
                if table[k, 5] != 0.0:
                    s += q[t, col]
                    col += 1
                cp, sp, cl, sl, h = math.cos(phi), math.sin(phi), math.cos(table[k, 1]), math.sin(table[k, 1]), table[k, 3]
                # columns of the H-D matrix: (cp, sp, 0), (-sp cl, cp cl, sl), (sp sl, -cp sl, cl), (h cp, h sp, s)
                b00, b01, b02, b03 = a00 * cp + a01 * sp, -a00 * sp * cl + a01 * cp * cl + a02 * sl, \
                    a00 * sp * sl - a01 * cp * sl + a02 * cl, a00 * h * cp + a01 * h * sp + a02 * s + a03
                b10, b11, b12, b13 = a10 * cp + a11 * sp, -a10 * sp * cl + a11 * cp * cl + a12 * sl, \
                    a10 * sp * sl - a11 * cp * sl + a12 * cl, a10 * h * cp + a11 * h * sp + a12 * s + a13
                b20, b21, b22, b23 = a20 * cp + a21 * sp, -a20 * sp * cl + a21 * cp * cl + a22 * sl, \
                    a20 * sp * sl - a21 * cp * sl + a22 * cl, a20 * h * cp + a21 * h * sp + a22 * s + a23
                a00, a01, a02, a03 = b00, b01, b02, b03
                a10, a11, a12, a13 = b10, b11, b12, b13
                a20, a21, a22, a23 = b20, b21, b22, b23
            M[t, 0, 0], M[t, 0, 1], M[t, 0, 2], M[t, 0, 3] = a00, a01, a02, a03
            M[t, 1, 0], M[t, 1, 1], M[t, 1, 2], M[t, 1, 3] = a10, a11, a12, a13
            M[t, 2, 0], M[t, 2, 1], M[t, 2, 2], M[t, 2, 3] = a20, a21, a22, a23
            M[t, 3, 0], M[t, 3, 1], M[t, 3, 2], M[t, 3, 3] = 0.0, 0.0, 0.0, 1.0
            P[t, 0] = a03 + a00 * px + a01 * py + a02 * pz
            P[t, 1] = a13 + a10 * px + a11 * py + a12 * pz
            P[t, 2] = a23 + a20 * px + a21 * py + a22 * pz

    def run(q):
        n = q.shape[0]
        M, P = np.empty((n, 4, 4)), np.empty((n, 3))
        loop(q, M, P)
        return M, P

    return run


def chain_inputs(n, dof):
    rng = np.random.default_rng(30)
    q = rng.uniform(-math.pi, math.pi, (n, dof))
    q[:, 2] = rng.uniform(0.1, 0.4, n)          # the slide of the P pair
    return q


def check_spatial(n=2000):
    """The plain loops agree with `mech` (NumPy path) to 1e-14 of the linkage's size."""
    import mech

    mech.set_backend("numpy")
    rssr, dims = rssr_subject()
    theta = 2.0 * np.pi * np.arange(n) / n
    pose, (phi03, B, C, P) = rssr.solve(theta), plain_rssr_loop(dims)(theta)
    assert np.array_equal(np.isnan(phi03), np.isnan(pose.phi03)) and not np.isnan(phi03).all()
    for got, want in ((B, pose.B), (C, pose.C), (P, pose.P)):
        ok = ~np.isnan(want[:, 0])
        assert np.max(np.abs(got[ok] - want[ok])) < 1e-14 * 2.5, "RSSR plain loop"
    chain, point = chain_subject()
    q = chain_inputs(n, chain.dof)
    pose, (M, P) = chain.solve(q, point=point), plain_chain_loop(chain, point)(q)
    assert np.max(np.abs(M - pose.M)) < 1e-14 and np.max(np.abs(P - pose.P)) < 1e-14, "chain plain loop"
    mech.set_backend("auto")


def batch_dims(n):
    """`n` four-bars of the atlas's design space that close (each link shorter than the other
    three together), of every Grashof type, branch +1 or -1."""
    rng = np.random.default_rng(30)
    a, b, c = np.exp(rng.uniform(np.log(0.2), np.log(5.0), (3, 3 * n)))
    d = np.ones(3 * n)
    L = np.stack([a, b, c, d])
    keep = np.flatnonzero((2 * L.max(axis=0) < L.sum(axis=0)))[:n]
    a, b, c, d = L[:, keep]
    return a, b, c, d, b * rng.uniform(-1, 2, n), b * rng.uniform(-1.5, 1.5, n), rng.choice([-1.0, 1.0], n)


def make(method, n):
    subject, kind = method.split("-")
    if subject == "batch":
        dims = batch_dims(BATCH[0] if n is None else n)
        theta = 2 * np.pi * (np.arange(BATCH[1]) + 0.5) / BATCH[1]
        if kind == "plain":
            run = plain_batch_loop()
            return lambda: run(dims, theta)
        import mech
        from mech.planar.kinematics._fourbar_batch import solve_fourbars

        mech.set_backend(kind)
        return lambda: solve_fourbars(*dims[:4], theta, coupler=dims[4:6], branch=dims[6])
    if subject == "rssr":
        rssr, dims = rssr_subject()
        theta = 2.0 * np.pi * np.arange(n) / n
        if kind == "plain":
            run = plain_rssr_loop(dims)
            return lambda: run(theta)
        import mech

        mech.set_backend(kind)
        return lambda: rssr.solve(theta)
    if subject == "chain":
        chain, point = chain_subject()
        q = chain_inputs(n, chain.dof)
        if kind == "plain":
            run = plain_chain_loop(chain, point)
            return lambda: run(q)
        import mech

        mech.set_backend(kind)
        return lambda: chain.solve(q, point=point)
    from mech.planar.special import _library as lib

    linkage = lib.jansen_linkage() if subject == "jansen" else lib.watt_six_bar()
    theta = 2.0 * np.pi * np.arange(n) / n
    if kind == "plain":
        run = plain_linkage_loop(linkage)
        return lambda: run(theta)
    return lambda: linkage.solve(theta)


def worker(method, n, calls):
    run = make(method, n)
    start = time.perf_counter()
    run()
    first = time.perf_counter() - start
    times, cpu = [], []
    for _ in range(calls):
        start, start_cpu = time.perf_counter(), time.process_time()
        run()
        times.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    print(json.dumps({"times": times, "cpu": cpu, "first_call_s": first}))


def spawn(method, n, calls):
    cmd = [sys.executable, str(Path(__file__).resolve()), "--worker", method, str(n), str(calls)]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=3600)
    if done.returncode != 0:
        raise RuntimeError(f"{method} N={n} failed:\n{done.stderr}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def measure(groups, rounds, calls, log):
    """Medians of the wall-clock and the CPU time of each (method, n)."""
    out = {}
    for n, methods in groups:
        samples = {m: {"times": [], "cpu": []} for m in methods}
        for _ in range(rounds):
            for m in methods:
                got = spawn(m, n, calls)
                for key in ("times", "cpu"):
                    samples[m][key] += got[key]
        for m in methods:
            out[(m, n)] = tuple(float(np.median(samples[m][key])) for key in ("times", "cpu"))
            log(f"{m:<14} n={n:>8} median wall {out[(m, n)][0] * 1e3:10.3f} ms, cpu {out[(m, n)][1] * 1e3:10.3f} ms")
    return out


def _ratio(t, x, y):
    """Ratios of wall-clock and CPU medians: under load the CPU time is the steadier."""
    return f"wall {t[x][0] / t[y][0]:.2f}, cpu {t[x][1] / t[y][1]:.2f}"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--only", choices=("linkage", "batch", "spatial"), help="measure one part")
    parser.add_argument("--sizes", type=int, nargs="+", help="numbers of poses (default 10^3, 10^4, 10^6)")
    parser.add_argument("--rounds", type=int, default=ROUNDS)
    parser.add_argument("--calls", type=int, default=CALLS)
    parser.add_argument("--worker", nargs=3, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        worker(args.worker[0], int(args.worker[1]), int(args.worker[2]))
        return 0
    log = lambda s: print(s, flush=True)  # noqa: E731
    log(f"load average at start: {os.getloadavg()}")
    sizes = tuple(args.sizes) if args.sizes else (10**3, 10**4) if args.quick else (10**3, 10**4, 10**6)
    batch = 10**4 if args.quick else BATCH[0]
    planar = args.only in (None, "linkage")
    spatial = args.only in (None, "spatial")
    groups = [] if not planar else [
        (n, [f"{s}-{k}" for s in ("jansen", "watt") for k in ("auto", "plain")]) for n in sizes]
    if spatial:
        check_spatial()
        groups += [(n, [f"{s}-{k}" for s in ("rssr", "chain") for k in ("auto", "numpy", "plain")]) for n in sizes]
    if args.only in (None, "batch"):
        groups.append((batch, ["batch-numba", "batch-numpy", "batch-plain"]))
    rounds, calls = (1, 3) if args.quick else (args.rounds, args.calls)
    t = measure(groups, rounds, calls, log)
    for n in sizes if planar else ():
        for s in ("jansen", "watt"):
            log(f"{s} N={n}: Linkage.solve (auto) / plain loop: {_ratio(t, (f'{s}-auto', n), (f'{s}-plain', n))}")
    for n in sizes if spatial else ():
        for s, name in (("rssr", "RSSR"), ("chain", "OpenChain")):
            for k in ("auto", "numpy"):
                log(f"{s} N={n}: {name}.solve ({k}) / plain loop: {_ratio(t, (f'{s}-{k}', n), (f'{s}-plain', n))}")
    if spatial:
        log("cost per pose (cpu, ns): " + "; ".join(
            f"{m} " + ", ".join(f"{t[(m, n)][1] / n * 1e9:.0f}" for n in sizes)
            for m in (f"{s}-{k}" for s in ("rssr", "chain") for k in ("auto", "numpy", "plain"))))
    if planar:
        # cost per pose (CPU medians): flat from the middle size to the largest is the goal
        log("cost per pose (cpu, ns): " + "; ".join(
            f"{m} " + ", ".join(f"{t[(m, n)][1] / n * 1e9:.0f}" for n in sizes)
            for m in (f"{s}-{k}" for s in ("jansen", "watt") for k in ("auto", "plain"))))
    for k in ("numba", "numpy") if args.only in (None, "batch") else ():
        log(f"batch {batch} x {BATCH[1]}: solve_fourbars ({k}) / plain loop: "
            f"{_ratio(t, (f'batch-{k}', batch), ('batch-plain', batch))}")
    log(f"load average at end: {os.getloadavg()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
