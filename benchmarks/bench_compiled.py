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

Subjects: ``Linkage.solve`` with the default backend (``auto``), and ``solve_fourbars`` on
each backend (``batch-numba``, ``batch-numpy``).

    python benchmarks/bench_compiled.py                 # N = 10^3, 10^4, 10^6, batch 10^5 x 128
    python benchmarks/bench_compiled.py --quick         # smaller, one round
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
    parser.add_argument("--only", choices=("linkage", "batch"), help="measure one part")
    parser.add_argument("--rounds", type=int, default=ROUNDS)
    parser.add_argument("--calls", type=int, default=CALLS)
    parser.add_argument("--worker", nargs=3, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        worker(args.worker[0], int(args.worker[1]), int(args.worker[2]))
        return 0
    log = lambda s: print(s, flush=True)  # noqa: E731
    log(f"load average at start: {os.getloadavg()}")
    sizes = (10**3, 10**4) if args.quick else (10**3, 10**4, 10**6)
    batch = 10**4 if args.quick else BATCH[0]
    groups = [] if args.only == "batch" else [
        (n, [f"{s}-{k}" for s in ("jansen", "watt") for k in ("auto", "plain")]) for n in sizes]
    if args.only != "linkage":
        groups.append((batch, ["batch-numba", "batch-numpy", "batch-plain"]))
    rounds, calls = (1, 3) if args.quick else (args.rounds, args.calls)
    t = measure(groups, rounds, calls, log)
    for n in sizes if args.only != "batch" else ():
        for s in ("jansen", "watt"):
            log(f"{s} N={n}: Linkage.solve (auto) / plain loop: {_ratio(t, (f'{s}-auto', n), (f'{s}-plain', n))}")
    if args.only != "batch":
        # cost per pose (CPU medians): flat from the middle size to the largest is the goal
        log("cost per pose (cpu, ns): " + "; ".join(
            f"{m} " + ", ".join(f"{t[(m, n)][1] / n * 1e9:.0f}" for n in sizes)
            for m in (f"{s}-{k}" for s in ("jansen", "watt") for k in ("auto", "plain"))))
    for k in ("numba", "numpy") if args.only != "linkage" else ():
        log(f"batch {batch} x {BATCH[1]}: solve_fourbars ({k}) / plain loop: "
            f"{_ratio(t, (f'batch-{k}', batch), ('batch-plain', batch))}")
    log(f"load average at end: {os.getloadavg()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
