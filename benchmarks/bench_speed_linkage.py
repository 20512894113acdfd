"""Benchmark: `Linkage`, the spherical four-bar, the RSSR and an open chain against compiled loops.

The solvers of issue 16, item 1 beyond the planar four-bar, timed as a user's script sees
them: each measurement in a new Python process (``--worker``), which builds the linkage,
makes one untimed call at the same N (numba's compile, first touch of memory) and then times
``CALLS`` calls; the processes of all methods are interleaved round after round, so a change
in the shared machine's load hits every method alike; each row is the median of
``ROUNDS x CALLS`` timings. Only ratios within one run are meaningful.

Subjects and their reference loops (positions, order 0, omega = 1):

- ``jansen``, ``watt``: `Linkage.solve` of Jansen's leg and the Watt six-bar of
  ``mech.planar.special``; the loop is compiled by numba from the linkage's own steps and
  calls numba-compiled copies of the same generated Assur-group functions
  (``rigid_body_position``, ``rrr_position``) pose by pose;
- ``spherical``: `SphericalFourBar.solve` (NumPy and numba backends); the loop is the
  generated numba kernel alone (as in ``bench_speed.py``);
- ``rssr``: `RSSR.solve` with a coupler point; the loop calls numba-compiled copies of the
  generated ``rssr_abc``, ``rssr_reach``, ``rssr_discriminant``, ``abc_solve``,
  ``rssr_points`` and ``rssr_coupler_point`` pose by pose;
- ``chain``: `OpenChain.solve` of a 6R arm; the loop multiplies the 4 x 4 matrices of the
  generated ``hd_entries`` pose by pose.

Rows ``*-whole`` solve the same inputs in one piece (the block size set above N), as
before the blocks of issue 16: they show what the blocks buy. Peak memory per point at
N = 10^6 and 10^7 is measured in further fresh processes: the growth of the peak resident
set size over one call (``resource``) and the peak of NumPy's traced allocations
(``tracemalloc``; numba's allocations are outside it), beside the size of the result.

Results go to ``benchmarks/results/speed.json`` under the key ``"linkages"`` (the rest of
the file, written by ``bench_speed.py``, is kept); the book's benchmark page tabulates them.

    python benchmarks/bench_speed_linkage.py            # full run (about half an hour)
    python benchmarks/bench_speed_linkage.py --quick    # small sizes, nothing written
"""

from __future__ import annotations

import argparse
import datetime as _dt
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
OUTPUT = HERE / "results" / "speed.json"
KEY = "linkages"
SIZES = (10**3, 10**4, 10**5, 10**6)
ROUNDS, CALLS = 3, 7
MEMORY_SIZES = (10**6, 10**7)

#: method -> (subject, description)
METHODS = {
    "jansen-mech": ("jansen", "Linkage.solve, Jansen's leg (blocks)"),
    "jansen-whole": ("jansen", "Linkage.solve in one piece (no blocks)"),
    "jansen-loop": ("jansen", "numba loop of the same generated functions (reference)"),
    "watt-mech": ("watt", "Linkage.solve, Watt six-bar (blocks)"),
    "watt-whole": ("watt", "Linkage.solve in one piece (no blocks)"),
    "watt-loop": ("watt", "numba loop of the same generated functions (reference)"),
    "spherical-mech": ("spherical", "SphericalFourBar.solve, NumPy backend"),
    "spherical-numba": ("spherical", "SphericalFourBar.solve, numba backend"),
    "spherical-loop": ("spherical", "generated numba kernel alone (reference)"),
    "rssr-mech": ("rssr", "RSSR.solve with a coupler point (blocks)"),
    "rssr-whole": ("rssr", "RSSR.solve in one piece (no blocks)"),
    "rssr-loop": ("rssr", "numba loop of the same generated functions (reference)"),
    "chain-mech": ("chain", "OpenChain.solve, 6R arm (blocks)"),
    "chain-whole": ("chain", "OpenChain.solve in one piece (no blocks)"),
    "chain-loop": ("chain", "numba loop of the generated H-D entries (reference)"),
}
RSSR_DIMS = dict(l1=1.0, l2=4.0, l3=2.0, s0=0.5, s3=0.8, h0=3.0, lam=math.radians(60), coupler=(1.0, 0.5, 0.2))
CHAIN = ((math.pi / 2, 0.4, 0.0), (0.0, 0.0, 0.6), (0.0, 0.0, 0.5), (math.pi / 2, 0.1, 0.0),
         (-math.pi / 2, 0.0, 0.0), (0.0, 0.1, 0.0))         # (lam, s, h) of each R joint
CHAIN_POINT = (0.05, 0.0, 0.1)


# ----------------------------------------------------------------------------- worker side
def _njit(function):
    import numba

    return numba.njit(cache=False)(function)


def _linkage(subject):
    from mech.planar.special import _library as lib

    return lib.jansen_linkage() if subject == "jansen" else lib.watt_six_bar()


def linkage_loop(linkage):
    """A numba loop over the poses of a one-crank linkage of ground points, a crank, RRR
    groups and points on links, written from its steps; it calls the generated functions."""
    from mech._generated import assur_groups as g

    index, lines = {}, []

    def var(name):
        return index.setdefault(name, f"p{len(index)}")

    for step in linkage._steps:
        if step.kind == "ground":
            lines.append(f"{var(step.label)} = {complex(step.get('at'))!r}")
        elif step.kind == "crank":
            link, pivot, tip = step.links[0], var(step.get("pivot")), var(step.get("tip"))
            lines += [f"d_{link} = cmath.exp(1j * theta[t])",
                      f"x, y = rbp({pivot}.real, {pivot}.imag, d_{link}.real, d_{link}.imag, {step.get('length')!r}, 0.0)",
                      f"{tip} = complex(x, y)"]
        elif step.kind == "rrr":
            (l1, l2), (p1, p2), joint = step.links, step.get("pins"), var(step.get("joint"))
            (r1, r2), p1, p2 = step.get("lengths"), var(p1), var(p2)
            lines += [f"g = {p2} - {p1}",
                      f"ux, uy, D = rrr(g.real, g.imag, {r1!r}, {r2!r}, {float(step.get('branch'))!r})",
                      f"{joint} = {p1} + complex(ux, uy)",
                      f"d_{l1} = complex(ux, uy) / {r1!r}", f"d_{l2} = ({joint} - {p2}) / {r2!r}"]
        elif step.kind == "point":
            link, at = step.links[0], complex(step.get("at"))
            origin = next(s for s in linkage._steps if link in s.links and s.kind in ("crank", "rrr"))
            o = var(origin.get("pivot") if origin.kind == "crank" else
                    origin.get("pins")[origin.links.index(link)])
            lines += [f"x, y = rbp({o}.real, {o}.imag, d_{link}.real, d_{link}.imag, {at.real!r}, {at.imag!r})",
                      f"{var(step.label)} = complex(x, y)"]
        else:
            raise ValueError(f"no loop for a {step.kind} step")
    names = list(index)
    body = "\n".join("        " + line for line in lines)
    stores = "\n".join(f"        out[{k}, t] = {index[name]}" for k, name in enumerate(names))
    source = f"def loop(theta, out):\n    for t in range(theta.shape[0]):\n{body}\n{stores}\n"
    scope = {"cmath": __import__("cmath"), "rbp": _njit(g.rigid_body_position), "rrr": _njit(g.rrr_position)}
    exec(compile(source, f"<{linkage!r} loop>", "exec"), scope)
    loop = _njit(scope["loop"])

    def run(theta):
        out = np.empty((len(names), theta.size), complex)
        loop(theta, out)
        return out

    run.names = names
    return run


def _rssr():
    from mech.spatial._rssr import RSSR

    d = RSSR_DIMS
    return RSSR(d["l1"], d["l2"], d["l3"], d["s0"], d["s3"], d["h0"], d["lam"], coupler=d["coupler"])


def rssr_loop():
    """Pose by pose, the generated RSSR functions that `RSSR.solve` calls, compiled by numba."""
    from mech._generated import one_equation as one
    from mech._generated import rssr as gen

    linkage = _rssr()
    l1, l2, l3, s0, s3, h0, lam = linkage._dims()
    p, q, u = linkage._unit_coupler
    scale = linkage._scale
    abc, reach, factored = _njit(gen.rssr_abc), _njit(gen.rssr_reach), _njit(gen.rssr_discriminant)
    plain, solve = _njit(one.abc_discriminant), _njit(one.abc_solve)
    points, coupler = _njit(gen.rssr_points), _njit(gen.rssr_coupler_point)

    def loop(phi01, phi03, B, C, P):
        for t in range(phi01.shape[0]):
            A_, B_, C_ = abc(l1, l2, l3, s0, s3, h0, lam, phi01[t])
            _, rho, r2 = reach(l1, l2, l3, s0, s3, h0, lam, phi01[t])
            disc = factored(l1, l3, rho, math.sqrt(r2)) if r2 >= 0.0 else plain(A_, B_, C_)
            angle = solve(A_, B_, C_, math.sqrt(disc), 1.0) if disc >= 0.0 else math.nan
            bx, by, bz, cx, cy, cz = points(l1, l3, s0, s3, h0, lam, phi01[t], angle)
            px, py, pz = coupler(bx, by, bz, cx, cy, cz, l2, lam, p, q, u)
            phi03[t] = angle
            B[t, 0], B[t, 1], B[t, 2] = bx * scale, by * scale, bz * scale
            C[t, 0], C[t, 1], C[t, 2] = cx * scale, cy * scale, cz * scale
            P[t, 0], P[t, 1], P[t, 2] = px * scale, py * scale, pz * scale

    loop = _njit(loop)

    def run(phi01):
        n = phi01.size
        out = np.empty(n), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3))
        loop(phi01, *out)
        return out

    return run


def _chain():
    from mech.spatial._chain import Joint, OpenChain

    return OpenChain([Joint("R", lam=lam, s=s, h=h) for lam, s, h in CHAIN])


def chain_inputs(theta):
    """Joint angles of the 6R arm: joint k turns k + 1 times as fast as the first."""
    return np.stack([np.mod((k + 1) * theta, 2 * np.pi) for k in range(len(CHAIN))], axis=-1)


def chain_loop():
    """Pose by pose, the product of the generated H-D matrices (2-73) and the end point."""
    from mech._generated import transforms as gen

    entries = _njit(gen.hd_entries)
    params = np.array(CHAIN)
    point = np.array(CHAIN_POINT)

    def loop(q, M, P):
        T = np.empty((4, 4))
        H = np.empty((4, 4))
        R = np.empty((4, 4))
        for t in range(q.shape[0]):
            T[:] = 0.0
            for i in range(4):
                T[i, i] = 1.0
            for k in range(params.shape[0]):
                (H[0, 0], H[0, 1], H[0, 2], H[0, 3], H[1, 0], H[1, 1], H[1, 2], H[1, 3],
                 H[2, 0], H[2, 1], H[2, 2], H[2, 3]) = entries(q[t, k], params[k, 0], params[k, 1], params[k, 2])
                H[3, 0], H[3, 1], H[3, 2], H[3, 3] = 0.0, 0.0, 0.0, 1.0
                for i in range(3):
                    for j in range(4):
                        R[i, j] = T[i, 0] * H[0, j] + T[i, 1] * H[1, j] + T[i, 2] * H[2, j] + T[i, 3] * H[3, j]
                T[:3] = R[:3]
            M[t] = T
            for i in range(3):
                P[t, i] = T[i, 3] + T[i, 0] * point[0] + T[i, 1] * point[1] + T[i, 2] * point[2]

    loop = _njit(loop)

    def run(theta):
        q = chain_inputs(theta)
        M, P = np.empty((q.shape[0], 4, 4)), np.empty((q.shape[0], 3))
        loop(q, M, P)
        return M, P

    return run


def make(method):
    """The function of the crank angles that one row times."""
    subject, kind = method.split("-")
    sys.path.insert(0, str(HERE))
    if subject == "spherical":
        import bench_speed as bs

        return bs._spherical_loop() if kind == "loop" else bs._spherical_mech("numba" if kind == "numba" else "numpy")
    if kind == "whole":                      # one piece: the block size above any N
        from mech.planar.kinematics._linkage import _blocks as _linkage_blocks
        from mech.spatial import _chain as chain_module
        from mech.spatial import _rssr as rssr_module

        _linkage_blocks.BLOCK = rssr_module._BLOCK = chain_module._BLOCK = 10**12
    if subject in ("jansen", "watt"):
        linkage = _linkage(subject)
        return linkage_loop(linkage) if kind == "loop" else (lambda theta: linkage.solve(theta))
    if subject == "rssr":
        if kind == "loop":
            return rssr_loop()
        linkage = _rssr()
        return lambda theta: linkage.solve(theta)
    if kind == "loop":
        return chain_loop()
    chain = _chain()
    return lambda theta: chain.solve(chain_inputs(theta), point=CHAIN_POINT)


def result_bytes(result):
    """Bytes held by the arrays of a result (views and broadcasts counted once, at their base)."""
    seen, total = set(), 0
    stack = [result]
    while stack:
        x = stack.pop()
        if isinstance(x, np.ndarray):
            base = x
            while isinstance(base.base, np.ndarray):
                base = base.base
            if id(base) not in seen and all(s != 0 for s in base.strides):
                seen.add(id(base))
                total += base.nbytes
        elif isinstance(x, (tuple, list)):
            stack.extend(x)
        elif hasattr(x, "_fields"):
            stack.extend(x._fields.values())
        elif hasattr(x, "points"):            # LinkageSolution
            stack += [x.valid, *x.points.values(), *x._dirs.values(), *x.failures.values()]
    return total


def theta_grid(n):
    return 2.0 * np.pi * np.arange(n) / n


def worker(method, n, calls, memory):
    """Run in a fresh process; print one JSON line."""
    theta = theta_grid(n)
    run = make(method)
    if memory:
        import resource
        import tracemalloc

        run(theta_grid(1000))                        # compile / load kernels on a small input
        before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        result = run(theta)
        rss = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before) * 1024
        size = result_bytes(result)
        del result
        tracemalloc.start()
        result = run(theta)
        traced = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        print(json.dumps({"rss_growth_bytes": rss, "tracemalloc_peak_bytes": traced, "result_bytes": size}))
        return
    start = time.perf_counter()
    run(theta)                                        # untimed: compile, first touch
    first = time.perf_counter() - start
    times = []
    for _ in range(calls):
        start = time.perf_counter()
        run(theta)
        times.append(time.perf_counter() - start)
    print(json.dumps({"times": times, "first_call_s": first}))


# ----------------------------------------------------------------------------- driver side
def spawn(method, n, calls=0, memory=False):
    cmd = [sys.executable, str(Path(__file__).resolve()), "--worker", method, str(n), str(calls)]
    if memory:
        cmd.append("--memory")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=3600)
    if done.returncode != 0:
        raise RuntimeError(f"{method} N={n} failed:\n{done.stderr}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def measure(sizes, methods, rounds, calls, log):
    rows = []
    for n in sizes:
        samples = {m: [] for m in methods}
        for _ in range(rounds):
            for m in methods:                         # interleaved: every method once per round
                samples[m] += spawn(m, n, calls)["times"]
        for m in methods:
            t = np.array(samples[m])
            rows.append({"method": m, "subject": METHODS[m][0], "n": n, "median_s": float(np.median(t)),
                         "min_s": float(t.min()), "samples": int(t.size),
                         "ns_per_point": float(np.median(t) / n * 1e9)})
            log(f"N={n:>9} {m:<18} {rows[-1]['ns_per_point']:10.1f} ns/point  (median of {t.size})")
    return rows


def memory(sizes, methods, log):
    rows = []
    for n in sizes:
        for m in methods:
            got = spawn(m, n, memory=True)
            rows.append({"method": m, "subject": METHODS[m][0], "n": n, **got,
                         "rss_bytes_per_point": got["rss_growth_bytes"] / n,
                         "tracemalloc_bytes_per_point": got["tracemalloc_peak_bytes"] / n,
                         "result_bytes_per_point": got["result_bytes"] / n})
            log(f"memory N={n:>9} {m:<18} rss {rows[-1]['rss_bytes_per_point']:7.1f} B/point, traced "
                f"{rows[-1]['tracemalloc_bytes_per_point']:7.1f}, result {rows[-1]['result_bytes_per_point']:7.1f}")
    return rows


def ratios(rows):
    """Per subject and N: time of each mech row over the reference loop's."""
    time_of = {(r["method"], r["n"]): r["median_s"] for r in rows}
    out = {}
    for (method, n), t in time_of.items():
        subject, kind = method.split("-")
        loop = time_of.get((f"{subject}-loop", n))
        if kind != "loop" and loop:
            out[f"{method}_vs_loop_{n:.0e}".replace("+0", "").replace("+", "")] = {
                "value": t / loop, "numerator": method, "denominator": f"{subject}-loop", "n": n}
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="N = 10^3, 10^4, 1 round of 3 calls; nothing written")
    parser.add_argument("--sizes", help="comma-separated N to measure again; their rows replace those "
                        "of the last run (memory rows kept)")
    parser.add_argument("--worker", nargs=3, metavar=("METHOD", "N", "CALLS"), help=argparse.SUPPRESS)
    parser.add_argument("--memory", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        worker(args.worker[0], int(args.worker[1]), int(args.worker[2]), args.memory)
        return 0
    methods = list(METHODS)
    log = lambda s: print(s, flush=True)  # noqa: E731
    start = time.perf_counter()
    previous = json.loads(OUTPUT.read_text()).get(KEY) if OUTPUT.exists() else None
    if args.quick:
        rows, mem = measure((10**3, 10**4), methods, 1, 3, log), []
    elif args.sizes and previous:
        sizes = tuple(int(float(x)) for x in args.sizes.split(","))
        rows = [r for r in previous["rows"] if r["n"] not in sizes] + measure(sizes, methods, ROUNDS, CALLS, log)
        rows.sort(key=lambda r: (r["n"], methods.index(r["method"])))
        mem = previous["memory"]
    else:
        rows = measure(SIZES, methods, ROUNDS, CALLS, log)
        mem = memory(MEMORY_SIZES, methods, log)
    result = {
        "benchmark": "bench_speed_linkage",
        "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
        "protocol": {"rounds": ROUNDS, "calls": CALLS, "fresh_process_per_measurement": True,
                     "interleaved": True},
        "methods": {m: {"subject": s, "description": d} for m, (s, d) in METHODS.items()},
        "rows": rows, "memory": mem, "ratios": ratios(rows), "wall_s": time.perf_counter() - start,
    }
    for name, r in result["ratios"].items():
        log(f"{name:<34} {r['value']:8.2f}")
    if not args.quick:
        data = json.loads(OUTPUT.read_text()) if OUTPUT.exists() else {}
        data[KEY] = result
        OUTPUT.write_text(json.dumps(data, indent=1) + "\n")
        log(f"wrote {OUTPUT} [{KEY!r}]")
    return 0


if __name__ == "__main__":
    sys.exit(main())
