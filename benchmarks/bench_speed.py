"""Benchmark: time per point against N as a user's script sees it, each run in a fresh process.

Every timing runs in a new Python process (``--worker``): it builds the linkage, makes one
untimed call at the same N (numba's compile or cache load, first-touch of memory), then times
a few calls. The processes of the methods are interleaved, round after round, so a change in
the shared machine's load hits every method alike; each row is the median of 21 timings
(3 processes x 7 calls; at N = 10^7, 1 process x 5 calls). Only ratios within one run are
meaningful. Peak memory per point at N = 10^6 and 10^7 is measured in further fresh
processes, as the growth of the peak resident set size over one call (``resource``) and as
the peak of NumPy's traced allocations (``tracemalloc``; numba allocates outside it).

Rows (planar four-bar ``FourBar(1, 4, 3, 3.5, coupler=(2, 1))``, omega = 1, alpha = 0):

- ``mech-numpy``: ``solve(theta)`` with ``mech.set_backend("numpy")`` (the default install);
- ``mech-numba``: the same with the numba backend (``pip install mech[fast]``);
- ``loop``: the reference, the generated numba kernel of the same expressions called once
  over all points into preallocated outputs: no validation, no masks, nothing else;
- ``pylinkage``: pylinkage 1.3's numba-compiled ``step_fast`` (``step_fast_with_kinematics``
  at order 2);
- ``root``: the per-pose route, ``scipy.optimize.root`` per angle (N <= 10^4);

each at order 0 (positions) and, for mech, the loop and pylinkage, order 2. Then ``Linkage``
(Jansen's leg, the Watt six-bar of ``mech.planar``) against a numba loop of the law of
cosines per pose, and the spherical four-bar against the generated numba kernel.
Results go to ``benchmarks/results/speed.json``; the book's benchmark page plots them.

    python benchmarks/bench_speed.py            # full run (10 to 25 minutes, with the load)
    python benchmarks/bench_speed.py --quick    # small sizes, nothing written
"""

from __future__ import annotations

import argparse
import datetime as _dt
import importlib.metadata
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
OUTPUT = HERE / "results" / "speed.json"
SIZES = (10**2, 10**3, 10**4, 10**5, 10**6, 10**7)
ROUNDS, CALLS = 3, 7
ROUNDS_LARGE, CALLS_LARGE = 1, 5          # at 10^7
MEMORY_SIZES = (10**6, 10**7)
GOALS = {
    "mech_numpy_vs_loop_1e4": 2.0, "mech_numpy_vs_loop_1e6": 2.0,
    "mech_numba_vs_loop_1e4": 1.2, "mech_numba_vs_loop_1e6": 1.2,
    "pylinkage_vs_mech_1e4": 3.0, "pylinkage_vs_mech_1e6": 5.0,
    "order2_vs_order0_1e4": 3.0, "order2_vs_order0_1e6": 3.0,
}

#: method -> (subject, order, largest N, description)
METHODS = {
    "mech-numpy": ("fourbar", 0, 10**7, "FourBar.solve, NumPy backend (default install)"),
    "mech-numba": ("fourbar", 0, 10**7, "FourBar.solve, numba backend"),
    "loop": ("fourbar", 0, 10**7, "generated numba kernel alone (reference)"),
    "pylinkage": ("fourbar", 0, 10**7, "pylinkage 1.3 step_fast (numba)"),
    "root": ("fourbar", 0, 10**4, "scipy.optimize.root per angle"),
    "mech-numpy-o2": ("fourbar", 2, 10**7, "FourBar.solve(order=2), NumPy backend"),
    "mech-numba-o2": ("fourbar", 2, 10**7, "FourBar.solve(order=2), numba backend"),
    "loop-o2": ("fourbar", 2, 10**7, "generated numba kernels alone, order 2 (reference)"),
    "pylinkage-o2": ("fourbar", 2, 10**6, "pylinkage 1.3 step_fast_with_kinematics"),
    "jansen-mech-numpy": ("jansen", 0, 10**6, "Linkage.solve, Jansen's leg, NumPy backend"),
    "jansen-loop": ("jansen", 0, 10**6, "numba loop, law of cosines per pose (reference)"),
    "watt-mech-numpy": ("watt", 0, 10**6, "Linkage.solve, Watt six-bar, NumPy backend"),
    "watt-loop": ("watt", 0, 10**6, "numba loop, law of cosines per pose (reference)"),
    "spherical-mech-numpy": ("spherical", 0, 10**6, "SphericalFourBar.solve, NumPy backend"),
    "spherical-mech-numba": ("spherical", 0, 10**6, "SphericalFourBar.solve, numba backend"),
    "spherical-loop": ("spherical", 0, 10**6, "generated numba kernel alone (reference)"),
}
FOURBAR = dict(a=1.0, b=4.0, c=3.0, d=3.5, coupler=(2.0, 1.0))
SPHERICAL = dict(arcs=(0.3, 0.9, 0.7, 1.0), coupler=(0.4, 0.5))


# ----------------------------------------------------------------------------- worker side
def _fourbar_mech(backend, order):
    import mech
    from mech.planar import FourBar

    mech.set_backend(backend)
    linkage = FourBar(FOURBAR["a"], FOURBAR["b"], FOURBAR["c"], FOURBAR["d"], coupler=FOURBAR["coupler"])
    return lambda theta: linkage.solve(theta, order=order)


def _fourbar_loop(order):
    """The generated numba kernels of the four-bar, called once over all points."""
    from mech._generated import fourbar_position as gen
    from mech._generated import fourbar_position_numba as nb

    a, b, c, d = FOURBAR["a"], FOURBAR["b"], FOURBAR["c"], FOURBAR["d"]
    p, q = FOURBAR["coupler"]
    gaps = [float(g) for g in gen.fourbar_assembly_gaps(a, b, c, d)]

    def run(theta):
        n = theta.size
        B, C, P, S = np.empty(n, complex), np.empty(n, complex), np.empty(n, complex), np.empty(n)
        nb.fourbar_position_kernel(a, b, c, d, p, q, theta, 1.0, *gaps,
                                   B.real, B.imag, C.real, C.imag, P.real, P.imag, S)
        if order < 2:
            return B, C, P
        omega, alpha = np.ones(n), np.zeros(n)
        w2, w3, vB, vC, vP = np.empty(n), np.empty(n), np.empty(n, complex), np.empty(n, complex), np.empty(n, complex)
        nb.fourbar_velocity_kernel(b, d, p, q, B.real, B.imag, C.real, C.imag, S, 1.0, omega,
                                   w2, w3, vB.real, vB.imag, vC.real, vC.imag, vP.real, vP.imag)
        a2, a3, aB, aC, aP = np.empty(n), np.empty(n), np.empty(n, complex), np.empty(n, complex), np.empty(n, complex)
        nb.fourbar_acceleration_kernel(b, d, p, q, B.real, B.imag, C.real, C.imag, S, 1.0, omega, alpha, w2, w3,
                                       a2, a3, aB.real, aB.imag, aC.real, aC.imag, aP.real, aP.imag)
        return B, C, P, vB, vC, vP, aB, aC, aP

    return run


def _pylinkage(order, n):
    sys.path.insert(0, str(HERE))
    from bench_coupler_curve import _pylinkage_step, pylinkage_build

    linkage, ip = pylinkage_build(n)
    return lambda theta: _pylinkage_step(linkage, ip, order, theta.size)


def _root():
    sys.path.insert(0, str(HERE))
    from bench_coupler_curve import scipy_runner

    return scipy_runner(0, 1e-13)


def _pin_loop():
    """numba versions of benchmarks/bench_linkage.py's per-pose law of cosines."""
    import cmath
    import math

    import numba

    @numba.njit(cache=False)
    def pin(P1, P2, r1, r2, side):
        g = P2 - P1
        d = abs(g)
        c = (r1 * r1 + d * d - r2 * r2) / (2.0 * r1 * d)
        return P1 + r1 * cmath.exp(1j * (math.atan2(g.imag, g.real) + side * math.acos(c)))

    return pin


def _linkage_mech(name, backend):
    import mech
    from mech.planar.special import _library as lib

    mech.set_backend(backend)
    linkage = lib.jansen_linkage() if name == "jansen" else lib.watt_six_bar()
    return lambda theta: linkage.solve(theta).points


def _linkage_loop(name):
    import cmath
    import math

    import numba

    from mech.planar.special import _library as lib

    pin = _pin_loop()
    if name == "jansen":
        h = lib.JANSEN_HOLY_NUMBERS
        Z = complex(-h["a"], -h["l"])
        m, j, bb, dd, e, k, c, f, g, i, hh = (h[x] for x in "mjbdekcfgih")

        @numba.njit(cache=False)
        def loop(theta, out):
            for t in range(theta.shape[0]):
                A = m * cmath.exp(1j * theta[t])
                B = pin(A, Z, j, bb, -1.0)
                C = pin(Z, B, dd, e, 1.0)
                D = pin(A, Z, k, c, 1.0)
                E = pin(C, D, f, g, -1.0)
                F = pin(D, E, i, hh, 1.0)
                out[0, t], out[1, t], out[2, t], out[3, t], out[4, t], out[5, t] = A, B, C, D, E, F
        rows = 6
    else:
        turn = math.radians(-150.0)

        @numba.njit(cache=False)
        def loop(theta, out):
            for t in range(theta.shape[0]):
                B = 20.0 * cmath.exp(1j * theta[t])
                C = pin(B, 50.0 + 0j, 50.0, 45.0, 1.0)
                g = C - 50.0
                E = 50.0 + 44.0 * cmath.exp(1j * (math.atan2(g.imag, g.real) + turn))
                G = pin(E, 68.0 - 9.0j, 24.0, 18.0, -1.0)
                out[0, t], out[1, t], out[2, t], out[3, t] = B, C, E, G
        rows = 4

    def run(theta):
        out = np.empty((rows, theta.size), complex)
        loop(theta, out)
        return out

    return run


def _spherical_mech(backend):
    import mech
    from mech.spherical import SphericalFourBar

    mech.set_backend(backend)
    linkage = SphericalFourBar(*SPHERICAL["arcs"], coupler=SPHERICAL["coupler"])
    return lambda theta: linkage.solve(theta)


def _spherical_loop():
    from mech._generated import spherical_fourbar_numba as nb

    a, b, c, d = SPHERICAL["arcs"]
    r, gamma = SPHERICAL["coupler"]

    def run(theta):
        n = theta.size
        psi, B, C, P = np.empty(n), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 3))
        nb.spherical_fourbar_position_kernel(a, b, c, d, r, gamma, theta, -1.0, psi,
                                             *(X[:, k] for X in (B, C, P) for k in range(3)))
        return psi, B, C, P

    return run


def make(method, n):
    order = METHODS[method][1]
    if method.startswith("mech-"):
        return _fourbar_mech(method.split("-")[1], order)
    if method.startswith("loop"):
        return _fourbar_loop(order)
    if method.startswith("pylinkage"):
        return _pylinkage(order, n)
    if method == "root":
        return _root()
    subject = METHODS[method][0]
    if subject in ("jansen", "watt"):
        return _linkage_loop(subject) if method.endswith("loop") else _linkage_mech(subject, method.split("-")[-1])
    return _spherical_loop() if method.endswith("loop") else _spherical_mech(method.split("-")[-1])


def theta_grid(n):
    return 2.0 * np.pi * np.arange(n) / n


def worker(method, n, calls, memory):
    """Run in a fresh process; print one JSON line."""
    theta = theta_grid(n)
    run = make(method, n)
    if memory:
        import resource
        import tracemalloc

        run(theta_grid(1000))                       # compile / load kernels on a small input
        before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        result = run(theta)
        rss = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before) * 1024
        del result
        tracemalloc.start()
        result = run(theta)
        traced = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        print(json.dumps({"rss_growth_bytes": rss, "tracemalloc_peak_bytes": traced}))
        return
    start = time.perf_counter()
    run(theta)                                       # untimed: compile / cache load, first touch
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


def available(method):
    if "pylinkage" in method:
        try:
            importlib.metadata.version("pylinkage")
        except importlib.metadata.PackageNotFoundError:
            return False
    if method == "root":
        try:
            importlib.metadata.version("scipy")
        except importlib.metadata.PackageNotFoundError:
            return False
    return "numba" not in method and "loop" not in method or _has_numba()


def _has_numba():
    try:
        importlib.metadata.version("numba")
    except importlib.metadata.PackageNotFoundError:
        return False
    return True


def measure(sizes, methods, rounds, calls, log):
    rows = []
    for n in sizes:
        large = n >= 10**7
        r, c = (ROUNDS_LARGE, CALLS_LARGE) if large else (rounds, calls)
        todo = [m for m in methods if n <= METHODS[m][2]]
        samples = {m: [] for m in todo}
        firsts = {m: [] for m in todo}
        for _ in range(r):
            for m in todo:                          # interleaved: every method once per round
                k = 1 if (m == "root" and n >= 10**4) else c   # about a second per call
                got = spawn(m, n, k)
                samples[m] += got["times"]
                firsts[m].append(got["first_call_s"])
        load = os.getloadavg()[0]                  # after this N's rounds
        for m in todo:
            t = np.array(samples[m])
            subject, order, _, desc = METHODS[m]
            rows.append({"method": m, "subject": subject, "order": order, "n": n, "description": desc,
                         "median_s": float(np.median(t)), "min_s": float(t.min()), "samples": int(t.size),
                         "ns_per_point": float(np.median(t) / n * 1e9),
                         "first_call_median_s": float(np.median(firsts[m])), "load_1min": load})
            log(f"N={n:>9} {m:<22} {rows[-1]['ns_per_point']:10.1f} ns/point  (median of {t.size})")
    return rows


def memory(sizes, methods, log):
    rows = []
    for n in sizes:
        for m in methods:
            if n > METHODS[m][2] or m == "root":
                continue
            got = spawn(m, n, memory=True)
            rows.append({"method": m, "subject": METHODS[m][0], "order": METHODS[m][1], "n": n, **got,
                         "rss_bytes_per_point": got["rss_growth_bytes"] / n,
                         "tracemalloc_bytes_per_point": got["tracemalloc_peak_bytes"] / n})
            log(f"memory N={n:>9} {m:<22} rss {rows[-1]['rss_bytes_per_point']:7.1f} B/point, "
                f"traced {rows[-1]['tracemalloc_bytes_per_point']:7.1f} B/point")
    return rows


def ratios(rows):
    def t(method, n):
        for r in rows:
            if r["method"] == method and r["n"] == n:
                return r["median_s"]
        return None

    out = {}

    def add(name, num, den, n):
        x, y = t(num, n), t(den, n)
        if x is not None and y is not None:
            out[name] = {"value": x / y, "numerator": num, "denominator": den, "n": n, "goal": GOALS.get(name)}

    for n, tag in ((10**4, "1e4"), (10**6, "1e6"), (10**7, "1e7")):
        add(f"mech_numpy_vs_loop_{tag}", "mech-numpy", "loop", n)
        add(f"mech_numba_vs_loop_{tag}", "mech-numba", "loop", n)
        add(f"pylinkage_vs_mech_{tag}", "pylinkage", "mech-numpy", n)
        add(f"pylinkage_vs_mech_numba_{tag}", "pylinkage", "mech-numba", n)
        add(f"order2_vs_order0_{tag}", "mech-numpy-o2", "mech-numpy", n)
        add(f"order2_vs_order0_numba_{tag}", "mech-numba-o2", "mech-numba", n)
        add(f"mech_numpy_o2_vs_loop_o2_{tag}", "mech-numpy-o2", "loop-o2", n)
        add(f"root_vs_mech_{tag}", "root", "mech-numpy", n)
        for subject in ("jansen", "watt", "spherical"):
            add(f"{subject}_numpy_vs_loop_{tag}", f"{subject}-mech-numpy", f"{subject}-loop", n)
            add(f"{subject}_numba_vs_loop_{tag}", f"{subject}-mech-numba", f"{subject}-loop", n)
    for name, r in out.items():
        if r["goal"] is not None:
            r["pass"] = bool(r["value"] >= r["goal"]) if name.startswith("pylinkage") else bool(r["value"] <= r["goal"])
    return out


def versions():
    out = {"python": platform.python_version()}
    for name in ("numpy", "numba", "pylinkage", "scipy"):
        try:
            out[name] = importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            out[name] = None
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="N = 10^2..10^4, 1 round of 3 calls; nothing written")
    parser.add_argument("--worker", nargs=3, metavar=("METHOD", "N", "CALLS"), help=argparse.SUPPRESS)
    parser.add_argument("--memory", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        worker(args.worker[0], int(args.worker[1]), int(args.worker[2]), args.memory)
        return 0
    methods = [m for m in METHODS if available(m)]
    log = lambda s: print(s, flush=True)  # noqa: E731
    start = time.perf_counter()
    load_start = os.getloadavg()
    if args.quick:
        rows = measure((10**2, 10**3, 10**4), methods, 1, 3, log)
        mem = []
    else:
        rows = measure(SIZES, methods, ROUNDS, CALLS, log)
        mem = memory(MEMORY_SIZES, methods, log)
    log(f"load average {load_start} at the start, {os.getloadavg()} at the end")
    result = {
        "benchmark": "speed",
        "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
        "machine": {"platform": platform.platform(), "processor": platform.processor(), "cpus": os.cpu_count(),
                    # 1-, 5- and 15-minute load averages when the run started and ended (the
                    # machine is shared: other processes compete for its cores)
                    "load_average_start": list(load_start), "load_average_end": list(os.getloadavg())},
        "versions": versions(),
        "protocol": {"rounds": ROUNDS, "calls": CALLS, "rounds_1e7": ROUNDS_LARGE, "calls_1e7": CALLS_LARGE,
                     "fresh_process_per_measurement": True, "interleaved": True},
        "methods": {m: {"subject": s, "order": o, "max_n": x, "description": d} for m, (s, o, x, d) in METHODS.items()},
        "rows": rows,
        "memory": mem,
        "ratios": ratios(rows),
        "wall_s": time.perf_counter() - start,
    }
    for name, r in result["ratios"].items():
        goal = "" if r["goal"] is None else f" (goal {r['goal']}: {'PASS' if r['pass'] else 'FAIL'})"
        log(f"{name:<34} {r['value']:8.2f}{goal}")
    if not args.quick:
        # keep what other scripts store in the same file (bench_speed_linkage.py's "linkages")
        previous = json.loads(OUTPUT.read_text()) if OUTPUT.exists() else {}
        result.update({k: v for k, v in previous.items() if k not in result})
        OUTPUT.write_text(json.dumps(result, indent=1) + "\n")
        log(f"wrote {OUTPUT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
